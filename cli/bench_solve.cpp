// `radmesh bench solve`: time per iteration and time to convergence, side by side in one run.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <nlohmann/json.hpp>

#include "cli/counted.h"
#include "cli/bench.h"
#include "cli/bench_ranks.h"
#include "cli/bench_timing.h"
#include "cli/cell_solve.h"
#include "solver/cells/find_cells.h"
#include "solver/formfactors/direction_bins.h"
#include "solver/radiosity/cell_solver.h"
#include "cli/stats_json.h"
#include "solver/scene/scene_error.h"
#include "solver/meshing/meshing.h"
#include "solver/radiosity/progressive_solver.h"
#include "cli/scene_input.h"
#include "cli/solve_flags.h"

namespace radmesh::cli {

namespace {

bool reachedUnshot(const SolveOptions& o, double unshotFraction) {
  return o.untilUnshot > 0.0 && unshotFraction <= o.untilUnshot;
}

struct Timing {
  double msPerIteration = 0.0;  // median over the measured iterations
  int iterationsToUntil = 0;
  double secondsToUntil = 0.0;
  bool reached = false;
  double unshotFraction = 0.0;            // left at the end
  double emulatedSecondsPerIteration = 0.0;  // mesh back end: mean emulated MP-1 time
  double absorbedW = 0.0;
  int cacheHits = 0;  // rows the form-factor cache served (whole solves)
  int rounds = 0;                       // cells solve
  std::vector<RankFigures> ranks = {};  // a distributed run's processes
  RunShape shape = {};
};

// Solves until `until` (or the cap), timing every iteration; the median is robust to the noise of
// a shared machine.
Timing timeSolve(const Scene& scene, const std::vector<Patch>& patches, SolveOptions options, int maxIterations) {
  options.maxIterations = maxIterations;
  const double start = benchSeconds(options.threads);
  ProgressiveSolver solver(scene, patches, options);
  std::vector<double> perIteration;
  double emulated = 0.0;
  Timing t;
  while (!solver.done()) {
    const double before = benchSeconds(options.threads);
    const IterationRecord& r = solver.step();
    perIteration.push_back(benchSeconds(options.threads) - before);
    if (r.shotStats) emulated += r.shotStats->machineSeconds;
    t.cacheHits += r.cacheHits;
  }
  t.unshotFraction = solver.ledger().unshotFraction();
  t.absorbedW = solver.ledger().absorbed;
  t.emulatedSecondsPerIteration = perIteration.empty() ? 0.0 : emulated / double(perIteration.size());
  t.secondsToUntil = benchSeconds(options.threads) - start;
  t.msPerIteration = 1e3 * median(perIteration);
  t.iterationsToUntil = static_cast<int>(perIteration.size());
  t.reached = solver.convergence() >= options.until || reachedUnshot(options, t.unshotFraction);
  return t;
}

// The cells solve, round by round: its time per iteration is a round's time over the iterations
// the cells shot in it, the median over the rounds. With `ranks`, this process's part of a
// distributed solve: every process's figures, and each cell's shots per round for the model.
Timing timeCells(const Scene& scene, const std::vector<Patch>& patches, const CellPartition& partition,
                 SolveOptions options, int maxIterations, const CellSolveSettings& settings, CellRanks* ranks) {
  options.maxIterations = maxIterations;
  const std::vector<CellTraffic> sentBefore = ranks ? ranks->traffic() : std::vector<CellTraffic>();
  const double wallStart = wallSeconds();
  const double start = benchSeconds(options.threads);
  CellSolver solver(scene, patches, partition, options, settings, ranks);
  std::vector<double> perIteration;
  Timing t;
  std::vector<int> shotsBefore(solver.cellCount(), 0);
  while (!solver.done()) {
    const double before = benchSeconds(options.threads);
    const int iterations = solver.iterations();
    solver.round();
    if (solver.iterations() > iterations)
      perIteration.push_back((benchSeconds(options.threads) - before) / (solver.iterations() - iterations));
    if (!ranks) continue;
    const std::vector<CellFigures> cells = solver.cellFigures();
    std::vector<int>& shots = t.shape.shotsPerRound.emplace_back();
    for (size_t c = 0; c < cells.size(); ++c) shots.push_back(cells[c].iterations - shotsBefore[c]), shotsBefore[c] = cells[c].iterations;
  }
  t.unshotFraction = solver.ledger().unshotFraction();
  t.absorbedW = solver.ledger().absorbed;
  t.rounds = solver.rounds();
  t.secondsToUntil = benchSeconds(options.threads) - start;
  t.msPerIteration = 1e3 * median(perIteration);
  t.iterationsToUntil = solver.iterations();
  t.reached = reachedUnshot(options, t.unshotFraction);
  if (ranks) {
    const double wall = wallSeconds() - wallStart;
    std::vector<CellTraffic> sent = ranks->traffic();
    for (size_t r = 0; r < sent.size(); ++r) sent[r] = sent[r] - sentBefore[r];
    t.ranks = rankFigures(solver, sent);
    const std::vector<double> walls = ranks->allGather(wall);
    for (size_t r = 0; r < walls.size(); ++r) t.ranks[r].wallSeconds = walls[r];
    for (const CellFigures& cell : solver.cellFigures()) t.shape.cellPatches.push_back(cell.patches + cell.portalPatches);
    t.shape.cellLoads = solver.cellLoads();
    t.shape.links = solver.portalTraffic();
    t.shape.rounds = solver.rounds();
    t.shape.bins = static_cast<size_t>(directionBinCount(settings.portalBins));
    t.shape.figureBytes = 8.0 * static_cast<double>(solver.figureDoubles());
  }
  return t;
}

}  // namespace

nlohmann::json benchSolve(const BenchSolveArgs& args, CellRanks* ranks) {
  if (!args.csvStem.empty() && !ranks)
    throw OptionError("--csv writes the per-rank figures of a distributed run: give --distributed (under mpirun)");
  const Scene scene = loadCommandScene(args.scene, /*strict=*/false, args.daylight, args.up, args.metresPerUnit);
  const CellChoice cell = commandCell(scene, args.cellM, args.cellGiven);
  fmt::print("{}\n", cell.why);
  const std::vector<Patch> patches = meshScene(scene, cell.cellM);
  const bool cells = parseCells(args.cellsMode);
  const CellPartition partition = cells ? findCells(scene, patches) : CellPartition{};
  const Backend backend = parseBackend(args.backend);
  const std::vector<std::string> projections =
      backend == Backend::Mesh && !args.projectionsGiven ? std::vector<std::string>{"plane"} : args.projections;
  auto optionsOf = [&](const std::string& projection, int n, int k) {
    SolveOptions o = SolveFlags().options;  // `solve`'s preset and its --effects default
    o.effects = EffectsMode::Auto;
    o.backend = backend;
    o.machine = args.machine;
    o.projection = parseProjection(projection);
    o.resolution = n;
    o.shooters = k;
    o.until = args.until;
    o.untilUnshot = args.untilUnshot;
    o.threads = args.threads;
    o.formFactorCacheBytes = formFactorCacheBytes(backend, args.cacheMb);
    if (cells) requireCellsOptions(o);  // first: its fix (the native back end) may settle the rest
    validateOptions(o);
    return o;
  };
  // Every setting is checked before any is timed: a refusal comes first, not after minutes of rows.
  // The lists first, so that a refusal names the flag given (--resolutions, not --resolution).
  for (int n : args.resolutions) checkResolution(n, "--resolutions");
  for (const std::string& projection : projections)  // with cells, their refusal of the mesh comes first
    if (!cells && backend == Backend::Mesh && parseProjection(projection) != Projection::Plane)
      throw OptionError(fmt::format("--backend mesh runs the paper's single plane; --projections {} is native only: "
                                    "give --projections plane or --backend native",
                                    projection));
  for (const std::string& projection : projections)
    for (int n : args.resolutions)
      for (int k : args.shooters) optionsOf(projection, n, k);
  if (!args.cells.empty()) checkResolution(args.scalingResolution, "--scaling-resolution");
  for (double cell : args.cells)
    if (!(std::isfinite(cell) && cell > 0.0))
      throw OptionError(
          fmt::format("--scaling-cell-sizes {}: give cell sizes in metres greater than 0, e.g. 0.75,0.381", cell));
  nlohmann::json rows = nlohmann::json::array();
  CsvTable ranksCsv = ranksCsvTable(), modelCsv = modelCsvTable();
  fmt::print("scene {}: {} patches, threads {}, until C={:.2f}{}, {}; times are {}\n", scene.source, patches.size(),
             args.threads, args.until,
             args.untilUnshot > 0.0 ? fmt::format(" or {:g}% unshot", 100.0 * args.untilUnshot) : "",
             benchCacheText(args.cacheMb), args.threads == 1 ? "the solving thread's CPU time" : "wall time");
  if (cells)
    fmt::print("cells solve: {}, {}, {} shots a cell a round on average; ms/iteration: a round's time "
               "over its iterations, the median over the rounds\n",
               counted(std::ssize(partition.cells), "cell"), counted(std::ssize(partition.portals), "portal"),
               args.exchangeShots);
  if (backend == Backend::Mesh)
    fmt::print("PE grid {}, {} KB a PE\n", peGridText(args.machine), args.machine.memoryKb);
  fmt::print("{:<10} {:>6} {:>4} {:>14} {:>12} {:>12} {:>10} {:>8} {:>12}\n", "projection", "N", "k", "ms/iteration",
             "iterations", "s to stop", "it/s", "unshot", "MP-1 s/it");
  for (const std::string& projection : projections) {
    for (int n : args.resolutions) {
      for (int k : args.shooters) {
        const SolveOptions o = optionsOf(projection, n, k);
        const Timing t = cells ? timeCells(scene, patches, partition, o, args.maxIterations,
                                           {cell.cellM, args.exchangeShots, args.portalBins}, ranks)
                               : timeSolve(scene, patches, o, args.maxIterations);
        fmt::print("{:<10} {:>6} {:>4} {:>14.3f} {:>12}{} {:>12.3f} {:>10.1f} {:>7.2f}% {:>12}\n", projection, n, k,
                   t.msPerIteration, t.iterationsToUntil, t.reached ? " " : "+", t.secondsToUntil,
                   t.msPerIteration > 0 ? 1e3 / t.msPerIteration : 0.0, 100.0 * t.unshotFraction,
                   backend == Backend::Mesh ? fmt::format("{:.4f}", t.emulatedSecondsPerIteration) : "-");
        rows.push_back({{"projection", projection},
                        {"resolution", n},
                        {"shooters", k},
                        {"ms_per_iteration", t.msPerIteration},
                        {"iterations_to_until", t.iterationsToUntil},
                        {"seconds_to_until", t.secondsToUntil},
                        {"reached_until", t.reached},
                        {"unshot_fraction", t.unshotFraction},
                        {"emulated_seconds_per_iteration", t.emulatedSecondsPerIteration},
                        {"absorbed_w", t.absorbedW}});
        if (cells) rows.back()["rounds"] = t.rounds;
        if (!cells) rows.back()["cache_hits"] = t.cacheHits;
        if (ranks)
          rows.back()["distributed"] = reportRanks(t.ranks, t.shape, {projection, std::to_string(n), std::to_string(k)},
                                                   ranksCsv, modelCsv);
      }
    }
  }
  nlohmann::json scaling = nlohmann::json::array();
  if (!args.cells.empty()) {
    fmt::print("\nscaling with patch count (plane {}x{}, {} iterations each)\n", args.scalingResolution,
               args.scalingResolution, args.scalingIterations);
    fmt::print("{:>8} {:>10} {:>14} {:>16}\n", "cell m", "patches", "ms/iteration", "us/(patch+pixel)");
    for (double cell : args.cells) {
      const std::vector<Patch> mesh = meshScene(scene, cell);
      SolveOptions o;
      o.resolution = args.scalingResolution;
      o.until = 1.0;
      o.threads = args.threads;
      const Timing t = timeSolve(scene, mesh, o, args.scalingIterations);
      const double work = static_cast<double>(mesh.size()) + double(o.resolution) * o.resolution;
      fmt::print("{:>8.3f} {:>10} {:>14.3f} {:>16.5f}\n", cell, mesh.size(), t.msPerIteration,
                 1e3 * t.msPerIteration / work);
      scaling.push_back({{"cell", cell}, {"patches", mesh.size()}, {"ms_per_iteration", t.msPerIteration}});
    }
  }
  nlohmann::json result = {{"scene", scene.source}, {"patches", patches.size()}, {"backend", args.backend},
                            {"threads", args.threads}, {"cells", args.cellsMode}, {"until_unshot", args.untilUnshot},
                            {"clock", args.threads == 1 ? "thread cpu" : "wall"}, {"until", args.until},
                            {"cache_mb", args.cacheMb}, {"rows", rows}, {"scaling", scaling}};
  if (ranks) result["ranks"] = ranks->size();
  if (ranks && !args.csvStem.empty() && ranks->rank() == 0) {  // the stem needs ranks (refused above)
    writeCsv(args.csvStem + "-ranks.csv", ranksCsv);
    writeCsv(args.csvStem + "-model.csv", modelCsv);
    fmt::print("wrote {0}-ranks.csv, {0}-model.csv\n", args.csvStem);
  }
  if (backend == Backend::Mesh)
    result.update({{"pe_grid", peGridText(args.machine)}, {"pe_memory_kb", args.machine.memoryKb}});
  return result;
}

}  // namespace radmesh::cli
