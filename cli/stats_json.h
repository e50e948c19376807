#pragma once
// The `--stats FILE.json` document of a solve: figures per iteration and the energy ledger.
#include <nlohmann/json.hpp>
#include <string>

#include "solver/radiosity/effects_plan.h"
#include "solver/radiosity/progressive_solver.h"

namespace radmesh::cli {

// With "effects": the solver's plan.
// `seconds`: this run's; `resumedAt`: the iterations a checkpoint brought (0: none), whose
// seconds per_iteration keeps from the run that solved them.
nlohmann::json solveStats(const ProgressiveSolver& solver, const std::string& scene, double seconds, size_t resumedAt);
// {"emitted": W, "absorbed": W, ..., "imbalance": x}, with "portal_in" and "portal_out" for a cell.
nlohmann::json ledgerJson(const Ledger& ledger);

// The solve's options as --stats gives them: backend, projection, mapping, resolution, ratio,
// shooters, threads, until, until_unshot.
nlohmann::json optionsJson(const SolveOptions& o);
// {"occlusion": {"on": false, "reason": "..."}, ...}
nlohmann::json effectsJson(const EffectsPlan& plan);
// Compact, one line; makes the folder. Throws on I/O failure.
void writeJson(const std::string& path, const nlohmann::json& document);

}  // namespace radmesh::cli
