#include "solver/radiosity/accuracy.h"

#include <cmath>
#include <stdexcept>

namespace radmesh {

double relativeRmsError(const Scene& scene, const std::vector<Patch>& patches, const std::vector<Rgb>& radiosity,
                        const std::vector<Rgb>& reference) {
  if (radiosity.size() != patches.size() || reference.size() != patches.size())
    throw std::invalid_argument("relativeRmsError: solution and reference must be on the same mesh");
  double error = 0.0, norm = 0.0;
  for (size_t j = 0; j < patches.size(); ++j) {
    const Rgb d = radiosity[j] - reference[j];
    error += patches[j].areaM2 * glm::dot(d, d);
    const Rgb reflected = reference[j] - scene.materials[patches[j].material].emittance;
    norm += patches[j].areaM2 * glm::dot(reflected, reflected);
  }
  if (!(norm > 0.0)) throw std::invalid_argument("relativeRmsError: the reference reflects no light anywhere");
  return std::sqrt(error / norm);
}

}  // namespace radmesh
