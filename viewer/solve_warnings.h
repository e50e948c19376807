#pragma once
// What the panel warns of once a solve has stopped: what `radmesh solve` prints after it.
#include <string>
#include <vector>

#include "viewer/solver_snapshot.h"

namespace radmesh {

// Empty until the stopping rule is met; then the light left unshot when far from converged, and
// the light lost where no solve loses it (lostLightWarnings, solver/radiosity/ledger.h).
std::vector<std::string> solveWarnings(const SolverSnapshot& snapshot);

}  // namespace radmesh
