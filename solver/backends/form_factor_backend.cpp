#include "solver/backends/form_factor_backend.h"

#include "solver/backends/mesh/mesh_backend.h"
#include "solver/backends/native/native_backend.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

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
