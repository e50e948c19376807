#include "solver/backends/form_factor_backend.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <queue>
#include <stdexcept>

#include "solver/backends/mesh/mesh_backend.h"
#include "solver/backends/native/native_backend.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

void FormFactorBackend::restoreMachineState(const std::string& state) {
  if (!state.empty()) throw std::invalid_argument("this back end keeps no machine state, but some was given");
}

void FormFactorBackend::binDirections(std::span<const int>, int) {
  throw OptionError("directional portals (--portal-bins above 1) need each pixel's delta form factor summed per "
                    "receiver and per direction bin, which only the native back end does (the mesh machine sums a "
                    "pixel into its receiver alone): give --backend native, or --portal-bins 1");
}

void refuseNaNUnshotPower(std::span<const double> unshotPowerW) {
  for (std::size_t j = 0; j < unshotPowerW.size(); ++j)
    if (std::isnan(unshotPowerW[j]))
      throw SolveError(fmt::format("patch {} has a NaN unshot power, so no shooter can be chosen: a form factor "
                                   "or radiosity went NaN (a fault in radmesh or its back end)", j));
}

std::vector<int> FormFactorBackend::selectShooters(std::span<const double> unshotPowerW,
                                                   std::span<const int> tieRank, int k) {
  refuseNaNUnshotPower(unshotPowerW);
  auto before = [&](int a, int b) {  // a shoots before b
    if (unshotPowerW[a] != unshotPowerW[b]) return unshotPowerW[a] > unshotPowerW[b];
    return tieRank[a] < tieRank[b];
  };
  // A heap of the best k so far whose top is the weakest of them.
  std::priority_queue<int, std::vector<int>, decltype(before)> best(before);
  for (int j = 0; j < static_cast<int>(unshotPowerW.size()); ++j) {
    if (!(unshotPowerW[j] > 0.0)) continue;
    if (static_cast<int>(best.size()) < k) {
      best.push(j);
    } else if (before(j, best.top())) {
      best.pop();
      best.push(j);
    }
  }
  std::vector<int> shooters;
  for (; !best.empty(); best.pop()) shooters.push_back(best.top());
  std::reverse(shooters.begin(), shooters.end());  // strongest first
  return shooters;
}

double FormFactorBackend::updateReceivers(const FormFactorRow& row, double,
                                          const std::function<double(std::size_t)>& update) {
  double absorbed = 0.0;
  for (std::size_t r = 0; r < row.receivers.size(); ++r) absorbed += update(r);
  return absorbed;
}

void FormFactorBackend::testReceivers(const FormFactorRow& row, double, double,
                                      const std::function<int(std::size_t)>& test) {
  for (std::size_t r = 0; r < row.receivers.size(); ++r) test(r);
}

std::unique_ptr<FormFactorBackend> makeFormFactorBackend(const Scene& scene,
                                                         const std::vector<Patch>& patches,
                                                         const SolveOptions& options) {
  switch (options.backend) {
    case Backend::Native: return std::make_unique<NativeBackend>(scene, patches, options);
    case Backend::Mesh: return std::make_unique<MeshBackend>(scene, patches, options, meshBackendOptions(options));
  }
  throw OptionError("--backend must be native or mesh");
}

std::unique_ptr<FormFactorBackend> makeFormFactorBackend(const Scene& scene, const std::vector<Patch>& patches,
                                                         const Elements& elements, const SolveOptions& options) {
  switch (options.backend) {
    case Backend::Native: return std::make_unique<NativeBackend>(scene, patches, elements, options);
    case Backend::Mesh:
      return std::make_unique<MeshBackend>(scene, patches, elements.elements, options, meshBackendOptions(options));
  }
  throw OptionError("--backend must be native or mesh");
}

}  // namespace radmesh
