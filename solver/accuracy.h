#pragma once
// Error of a radiosity solution against a reference on the same mesh.
#include <vector>

#include "solver/patch.h"

namespace radmesh {

// Area-weighted relative RMS of B over patches: sqrt(sum A|B - Bref|^2 / sum A|Bref|^2), with |.|
// the Euclidean norm over RGB. Throws std::invalid_argument if the sizes differ or Bref is all zero.
double relativeRmsError(const std::vector<Patch>& patches, const std::vector<Rgb>& radiosity,
                        const std::vector<Rgb>& reference);

}  // namespace radmesh
