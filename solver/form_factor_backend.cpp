#include "solver/form_factor_backend.h"

#include "solver/mesh_backend.h"
#include "solver/native_backend.h"
#include "solver/scene_error.h"

namespace radmesh {

double FormFactorRow::hitFraction() const {
  double sum = backFaces;
  for (double f : formFactors) sum += f;
  return sum;
}

double FormFactorRow::escapedFraction() const {
  // Sums in another order differ in the last bits: a difference at rounding level is neither light
  // escaping a closed scene nor light created.
  const double escaped = capturedFraction - hitFraction();
  return escaped > 1e-12 * capturedFraction ? escaped : 0.0;
}

std::size_t FormFactorRow::bytes() const {
  return sizeof(FormFactorRow) + receivers.capacity() * sizeof(int) +
         formFactors.capacity() * sizeof(double);
}

std::unique_ptr<FormFactorBackend> makeFormFactorBackend(const Scene& scene,
                                                         const std::vector<Patch>& patches,
                                                         const SolveOptions& options) {
  switch (options.backend) {
    case Backend::Native: return std::make_unique<NativeBackend>(scene, patches, options);
    case Backend::Mesh: return std::make_unique<MeshBackend>(scene, patches, options, MeshBackendOptions{options.mapping});
  }
  throw OptionError("--backend must be native or mesh");
}

}  // namespace radmesh
