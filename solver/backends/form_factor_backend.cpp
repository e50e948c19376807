#include "solver/backends/form_factor_backend.h"

#include "solver/backends/mesh/mesh_backend.h"
#include "solver/backends/native/native_backend.h"
#include "solver/scene/scene_error.h"

#include <stdexcept>

namespace radmesh {

void FormFactorBackend::restoreMachineState(const std::string& state) {
  if (!state.empty()) throw std::invalid_argument("this back end keeps no machine state, but some was given");
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
