#pragma once
// What the solver checks of what it is handed, as the loaders check files.
#include <vector>

#include "solver/meshing/patch.h"
#include "solver/scene/scene.h"

namespace radmesh {

// Throws SceneError naming the element for a reflectance outside [0, 1], a negative or non-finite
// emittance, a NaN or infinite coordinate, a patch that is not a triangle or quad, has no area or
// names no material, no patches at all, or a broken light.
void validateSolverInput(const Scene& scene, const std::vector<Patch>& patches);

}  // namespace radmesh
