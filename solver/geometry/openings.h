#pragma once
// Where a scene is open: the parts of polygon edges no other edge covers, and the closed loops
// they form (a window hole, an open top). Daylight enters there (solver/io/daylight.h).
#include <string>
#include <vector>

#include "solver/scene/note_tally.h"
#include "solver/scene/scene.h"

namespace radmesh {

// A stretch of one polygon's edge, in that polygon's direction, that no other edge lies along.
struct BoundarySegment {
  Vec3 a, b;
  size_t polygon = 0;  // whose edge it is
};

// Every such stretch. Collinear edges of other polygons cover an edge piecewise, so T-junctions
// (a wall cut into pieces around a window) leave no boundary where the pieces meet their
// neighbours; another polygon's face covers the stretch that lies on it (a column standing on a
// floor). Edges within `tolerance` (metres) of each other count as one line.
std::vector<BoundarySegment> boundarySegments(const Scene& scene, double tolerance);

// The length of the scene's bounding-box diagonal, which tolerances are relative to.
double sceneDiagonal(const Scene& scene);

struct OpeningPolygon {
  // Counter-clockwise seen from the side the surrounding surfaces face: the polygon that would
  // close the hole, facing as they do (into a room, for a window in its walls).
  std::vector<Vec3> vertices;
  Vec3 inside{0.0};  // a point inside the polygon, from which to look through it
};

struct OpeningSearch {
  std::vector<OpeningPolygon> openings;
  NoteTally skipped;  // the loops that are not openings, and why
};

// The boundary segments chained into closed loops (to 1e-7 of sceneDiagonal: vertices welded,
// collinear runs merged into one edge). A loop that does not close, or that is not planar (a
// vertex off its plane by more than 1e-3 of its size), is skipped with a note saying so.
OpeningSearch findOpenings(const Scene& scene);

}  // namespace radmesh
