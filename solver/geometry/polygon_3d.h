#pragma once
// A planar polygon in space, tested in the plane of the two world axes its normal is most nearly
// perpendicular to.
#include <utility>
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

// The two world axes of the plane a normal is most nearly perpendicular to.
std::pair<int, int> dominantPlane(const Vec3& normal);

// Whether p, in the polygon's plane, lies inside it (its crossing number, in that plane).
bool insidePolygon(const std::vector<Vec3>& vertices, const Vec3& normal, const Vec3& p);

}  // namespace radmesh
