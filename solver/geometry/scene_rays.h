#pragma once
// Rays cast at a scene's polygons: whether light can leave it (the effects plan's escape, the lost-
// light warnings) and whether an opening looks out onto the model (daylight).
#include <vector>

#include "solver/geometry/openings.h"
#include "solver/geometry/point_grid.h"
#include "solver/scene/scene.h"

namespace radmesh {

// The scene's polygons in cubic buckets (a 64th of the scene's diagonal), for casting many rays:
// a ray tests the polygons of the buckets it passes through, nearest first.
class SceneRays {
 public:
  explicit SceneRays(const Scene& scene);
  // Whether the ray from `origin` along the unit `direction` meets a polygon other than `skip`
  // further than `fromM` metres away (a negative `fromM` counts a face the origin lies on). The
  // scene must outlive this.
  bool hits(const Vec3& origin, const Vec3& direction, double fromM, int skip = -1) const;

 private:
  const Scene& scene_;
  std::vector<Vec3> normals_;  // per polygon, Newell's (length twice the area)
  Vec3 lo_{0.0}, hi_{0.0};     // the polygons' box, grown by a bucket
  double bucket_ = 1.0;
  PointGrid grid_;
  std::vector<int> large_;  // polygons too large for the buckets
};

// Whether light can leave the scene: some ray meets no polygon, from the middle of one of the `open`
// stretches (32 directions spread over the sphere) or from a point inside a polygon (4 directions of
// its front, a different four for each). Where none does, every face looks into closed surfaces,
// and the open edges, if any, lie inside them (a lamp's quad hanging under a closed room's ceiling).
bool lightCanLeave(const Scene& scene, const std::vector<BoundarySegment>& open);

}  // namespace radmesh
