#include "viewer/solve_warnings.h"

#include <fmt/format.h>

namespace radmesh {

std::vector<std::string> solveWarnings(const SolverSnapshot& snapshot) {
  if (!snapshot.done) return {};
  std::vector<std::string> warnings;
  const double unshot = snapshot.ledger.unshotFraction();
  if (unshot > kFarFromConvergedUnshot)
    warnings.push_back(fmt::format("stopped with {:.0f}% of the power unshot: the light is far from converged. Step "
                                   "on, or stop on the unshot power (Parameters)",
                                   100.0 * unshot));
  for (std::string& lost : lostLightWarnings(snapshot.ledger, snapshot.sceneClosed)) warnings.push_back(std::move(lost));
  return warnings;
}

}  // namespace radmesh
