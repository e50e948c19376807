#include "cli/counted.h"
#include "cli/cell_solve.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>

#include "cli/interrupt.h"
#include "cli/progress.h"
#include "cli/stats_json.h"
#include "solver/cells/find_cells.h"
#include "solver/formfactors/direction_bins.h"
#include "solver/scene/scene_error.h"

namespace radmesh::cli {

std::unique_ptr<CellSolver> makeCellSolver(const Scene& scene, std::vector<Patch> patches, const SolveOptions& options,
                                           const CellSolveSettings& settings, CellRanks* ranks) {
  requireCellsOptions(options);
  const CellPartition partition = findCells(scene, patches);
  auto solver = std::make_unique<CellSolver>(scene, std::move(patches), partition, options, settings, ranks);
  fmt::print("cells: {}, {}, exchanging portal light after rounds of {} shots a cell on average, "
             "shared by unshot power, {}\n",
             counted(solver->cellCount(), "cell"), counted(solver->portalCount(), "portal"), settings.exchangeShots,
             settings.portalBins > 1 ? fmt::format("in {} direction bins", directionBinCount(settings.portalBins))
                                     : std::string("re-emitted diffusely"));
  return solver;
}

double solveCellsWithProgress(CellSolver& solver, bool quiet, const std::function<void(double seconds)>& afterRound) {
  Progress progress(solver.options());
  progress.withoutConvergence();
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  IterationRecord record;  // the building's, as Progress reads a solve's
  while (!solver.done() && !interrupted()) {
    solver.round();
    record.iteration = solver.iterations();
    record.ledger = solver.ledger();
    if (!quiet) progress.report(record, elapsed());
    if (afterRound) afterRound(elapsed());
  }
  if (!quiet && record.iteration > 0) progress.finish(record, elapsed());
  return elapsed();
}

void printCellsSummary(const CellSolver& solver, double seconds) {
  const Ledger l = solver.ledger();
  double portalTransfers = 0.0;
  for (const CellFigures& cell : solver.cellFigures()) portalTransfers += cell.ledger.portalIn;
  int elements = 0;
  for (const CellFigures& cell : solver.cellFigures()) elements += cell.elements;
  const std::string elementsText =
      solver.options().subdivide == Subdivide::Off ? "" : fmt::format(" ({} elements)", elements);
  // A round is not cut short (a resumed solve must meet the straight one at its rounds' ends).
  const int cap = solver.options().maxIterations;
  const std::string past = solver.iterations() > cap
                               ? fmt::format(" (past --max-iterations {}, which is checked between rounds)", cap)
                               : "";
  fmt::print("solved: {} patches{} in {} ({}), {} iterations in {} rounds{}, unshot {:.2f}%, {:.3f} s\n",
             solver.patches().size(), elementsText, counted(solver.cellCount(), "cell"),
             counted(solver.portalCount(), "portal"), solver.iterations(), solver.rounds(), past,
             100.0 * l.unshotFraction(), seconds);
  fmt::print("ledger: emitted {:.6g} W = {} + unshot {:.6g} (with what waits on portals) + not captured "
             "{:.6g} + escaped {:.6g}  (imbalance {:.1e}); {:.6g} W crossed portals\n",
             l.emitted, absorbedTerm(l), l.unshot, l.notCaptured, l.escaped, l.imbalance(), portalTransfers);
  if (const std::string outside = lightOutsideSentence(l); !outside.empty()) fmt::print("        {}\n", outside);
}

nlohmann::json cellsStats(const CellSolver& solver, const std::string& scene, double seconds, int resumedAt) {
  const SolveOptions& o = solver.options();
  nlohmann::json perCell = nlohmann::json::array();
  int elements = 0;
  for (const CellFigures& cell : solver.cellFigures()) {
    elements += cell.elements;
    perCell.push_back({{"name", cell.name},
                       {"patches", cell.patches},
                       {"elements", cell.elements},
                       {"portal_patches", cell.portalPatches},
                       {"iterations", cell.iterations},
                       {"unshot_fraction", cell.ledger.unshotFraction()},
                       {"waiting", cell.waitingW},
                       {"ledger", ledgerJson(cell.ledger)}});
  }
  nlohmann::json j = optionsJson(o);
  j.update({{"scene", scene},
          {"patches", solver.patches().size()},
          {"elements", elements},
          {"cells", solver.cellCount()},
          {"portals", solver.portalCount()},
          {"rounds", solver.rounds()},
          {"exchange_shots", solver.settings().exchangeShots},
          {"portal_bins", solver.settings().portalBins},
          {"iterations", solver.iterations()},
          {"unshot_fraction", solver.ledger().unshotFraction()},
          {"seconds", seconds},
          {"resumed_after_iterations", resumedAt},
          {"ledger", ledgerJson(solver.ledger())},
          {"per_cell", std::move(perCell)}});
  return j;
}

std::vector<RankFigures> rankFigures(const CellSolver& solver, const std::vector<CellTraffic>& traffic) {
  std::vector<RankFigures> out(traffic.size());
  const std::vector<CellFigures> cells = solver.cellFigures();
  for (size_t c = 0; c < cells.size(); ++c) {
    RankFigures& r = out.at(static_cast<size_t>(solver.owner(static_cast<int>(c))));
    const int patches = cells[c].patches + cells[c].portalPatches;
    ++r.cells;
    r.patches += patches;
    r.shots += cells[c].iterations;
    r.work += static_cast<double>(cells[c].iterations) * patches;
  }
  for (size_t r = 0; r < out.size(); ++r) out[r].sent = traffic[r];
  return out;
}

nlohmann::json distributedStats(const CellSolver& solver, const std::vector<CellTraffic>& traffic) {
  nlohmann::json perRank = nlohmann::json::array();
  const double rounds = std::max(solver.rounds(), 1);
  const std::vector<RankFigures> ranks = rankFigures(solver, traffic);
  for (size_t r = 0; r < ranks.size(); ++r) {
    const CellTraffic& t = ranks[r].sent;
    perRank.push_back({{"rank", r},
                       {"cells", ranks[r].cells},
                       {"patches", ranks[r].patches},
                       {"shots", ranks[r].shots},
                       {"work", ranks[r].work},
                       {"messages", t.messages},
                       {"bytes", t.bytes},
                       {"gathers", t.gathers},
                       {"gather_bytes", t.gatherBytes},
                       {"messages_per_round", t.messages / rounds},
                       {"bytes_per_round", t.bytes / rounds},
                       {"mpi_wait_seconds", t.waitSeconds}});
  }
  nlohmann::json owner = nlohmann::json::array();
  for (int c = 0; c < solver.cellCount(); ++c) owner.push_back(solver.owner(c));
  return {{"ranks", traffic.size()}, {"owner", std::move(owner)}, {"per_rank", std::move(perRank)}};
}

}  // namespace radmesh::cli
