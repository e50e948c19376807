#pragma once
// Slicing polygons into patches on a global grid (the paper's section 1.6).
#include <vector>

#include "solver/meshing/patch.h"
#include "solver/scene/scene.h"

namespace radmesh {

inline constexpr double kDefaultCellM = 0.381;  // 15 inches, the paper's grid

// Every polygon is cut by the planes x = k*cell, y = k*cell, z = k*cell that cross its face (the
// two axes spanning its dominant plane) into convex pieces within one cell each, then into
// triangles and convex quads. Area, orientation and material are kept. Throws OptionError for a
// cell that is not finite and positive, or that would make more than `maxPatches` patches.
std::vector<Patch> meshScene(const Scene& scene, double cellM = kDefaultCellM,
                             size_t maxPatches = 2'000'000);

}  // namespace radmesh
