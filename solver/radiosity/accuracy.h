#pragma once
// Error of a radiosity solution against a reference on the same mesh.
#include <vector>

#include "solver/meshing/patch.h"
#include "solver/scene/scene.h"

namespace radmesh {

// Area-weighted relative RMS of the reflected radiosity B - E over patches:
// sqrt(sum A|B - Bref|^2 / sum A|Bref - E|^2), with |.| the Euclidean norm over RGB. Emission is
// given, not computed: left in the norm, a bright lamp would make every error look small. Throws
// std::invalid_argument if the sizes differ or the reference reflects nothing.
double relativeRmsError(const Scene& scene, const std::vector<Patch>& patches, const std::vector<Rgb>& radiosity,
                        const std::vector<Rgb>& reference);

}  // namespace radmesh
