// `radmesh bench cells`: the cells solve beside the whole building's, side by side in one run.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "cli/counted.h"
#include "cli/bench.h"
#include "cli/bench_timing.h"
#include "parallel/thread_pool.h"
#include "solver/cells/find_cells.h"
#include "solver/io/scene_loader.h"
#include "solver/meshing/meshing.h"
#include "solver/radiosity/cell_solver.h"
#include "solver/scene/scene_error.h"

namespace radmesh::cli {

namespace {

// Per cell of the partition, the area-weighted mean reflected radiosity (B - E over RGB).
std::vector<double> reflectedPerCell(const Scene& scene, const std::vector<Patch>& patches,
                                     const CellPartition& partition, const std::vector<Rgb>& b) {
  std::vector<double> weighted(partition.cells.size(), 0.0), area(partition.cells.size(), 0.0);
  for (size_t j = 0; j < patches.size(); ++j) {
    const int c = partition.cellOfPatch[j];
    if (c == kOutsideCell) continue;
    const Rgb e = scene.materials[patches[j].material].emittance;
    weighted[c] += (channelSum(b[j]) - channelSum(e)) * patches[j].areaM2;
    area[c] += patches[j].areaM2;
  }
  for (size_t c = 0; c < weighted.size(); ++c) weighted[c] = area[c] > 0.0 ? weighted[c] / area[c] : 0.0;
  return weighted;
}

struct CellsRun {
  double seconds = 0.0;      // benchSeconds: one thread, its CPU time; more, wall time
  double wallSeconds = 0.0;
  int iterations = 0;
  int rounds = 0;
  std::size_t elements = 0;
  double unshotFraction = 0.0;
  std::vector<Rgb> radiosity;
};

CellsRun runCells(const Scene& scene, const std::vector<Patch>& patches, const CellPartition& partition,
                  SolveOptions o, const BenchCellsArgs& args) {
  const double start = benchSeconds(o.threads), wallStart = wallSeconds();
  CellSolver solver(scene, patches, partition, o, {args.cellM, args.exchangeShots, args.portalBins});
  while (!solver.done()) solver.round();
  const double seconds = benchSeconds(o.threads) - start, wall = wallSeconds() - wallStart;
  return {seconds, wall, solver.iterations(), solver.rounds(), solver.elements().elements.size(),
          solver.ledger().unshotFraction(), solver.radiosity()};
}

struct FocusRun {
  double setupSeconds = 0.0;  // the cell solvers built (the portals meshed, the lights shot)
  double seconds = 0.0;       // then, until the focus cell reached focusUnshot
  int iterations = 0;         // the focus cell's
  int buildingIterations = 0;
  double arrivedW = 0.0;      // the focus cell's light: emitted in it and come in through its portals
  int cell = 0;
  std::string name;
  bool reached = false;       // false: the solve ended first (--max-iterations, or nothing left)
};

// The camera's cell first: the time until its unshot power is at most focusUnshot of the light it
// has had (ledger input: emitted in it, lights' direct light on it, and what came in through its
// portals), once light has reached it; checked between rounds. One thread, its CPU time.
FocusRun focusRun(const Scene& scene, const std::vector<Patch>& patches, const CellPartition& partition,
                  const SolveOptions& o, const BenchCellsArgs& args) {
  FocusRun run;
  const double start = benchSeconds(o.threads);
  // The building's own stop must not come first: it would end the run short of the focus target.
  SolveOptions focused = o;
  focused.untilUnshot = std::min(o.untilUnshot, args.focusUnshot);
  CellSolver solver(scene, patches, partition, focused, {args.cellM, args.exchangeShots, args.portalBins});
  solver.focus(args.focusCell);  // a cell of the partition: benchScene checked it
  run.setupSeconds = benchSeconds(o.threads) - start;
  auto reached = [&] {
    const Ledger& l = solver.cellSolver(args.focusCell).ledger();
    return l.input() > 0.0 && l.unshotFraction() <= args.focusUnshot;
  };
  while (!solver.done() && !(solver.rounds() > 0 && reached())) solver.round();
  run.seconds = benchSeconds(o.threads) - start - run.setupSeconds;
  run.reached = solver.rounds() > 0 && reached();
  run.iterations = solver.cellFigures()[args.focusCell].iterations;
  run.buildingIterations = solver.iterations();
  run.arrivedW = solver.cellSolver(args.focusCell).ledger().input();
  run.cell = args.focusCell;
  run.name = solver.cellFigures()[args.focusCell].name;
  return run;
}

// "+" after a count where the solve stopped short of its target (--max-iterations), as bench solve marks it.
std::string iterationsText(int iterations, bool reached) { return fmt::format("{}{}", iterations, reached ? "" : "+"); }

// "2.0x faster", or "2.5x slower" for a ratio below 1.
std::string speedText(double ratio) {
  return ratio >= 1.0 ? fmt::format("{:.1f}x faster", ratio) : fmt::format("{:.1f}x slower", 1.0 / ratio);
}

const FocusRun& printFocus(const FocusRun& focus, const BenchCellsArgs& args) {
  fmt::print("{:<28} {:>10.3f} {:>10} {:>11}   cell {} ({}) {} {:g}% of its arriving light unshot, after {:.3f} s "
             "of setup; {} iterations in all cells\n",
             "focus cell first, 1 thread", focus.seconds, "", iterationsText(focus.iterations, focus.reached),
             args.focusCell, focus.name, focus.reached ? "to" : "stopped short of", 100.0 * args.focusUnshot,
             focus.setupSeconds, focus.buildingIterations);
  return focus;
}

nlohmann::json focusJson(const FocusRun& focus) {
  return {{"focus_cell", focus.cell},
          {"focus_seconds", focus.seconds},
          {"focus_setup_seconds", focus.setupSeconds},
          {"focus_iterations", focus.iterations},
          {"focus_building_iterations", focus.buildingIterations},
          {"focus_arrived_w", focus.arrivedW},
          {"focus_reached", focus.reached}};
}

// Per lit room, the cells solve's reflected light against the whole building's: the rooms, the
// largest and the mean of the errors.
struct RoomErrors {
  nlohmann::json rooms = nlohmann::json::array();
  double worst = 0.0, mean = 0.0;
  int counted = 0;
};

RoomErrors roomErrors(const Scene& scene, const std::vector<Patch>& patches, const CellPartition& partition,
                      const std::vector<Rgb>& whole, const std::vector<Rgb>& cells) {
  const std::vector<double> expected = reflectedPerCell(scene, patches, partition, whole);
  const std::vector<double> got = reflectedPerCell(scene, patches, partition, cells);
  double largest = 0.0;
  for (double e : expected) largest = std::max(largest, e);
  RoomErrors r;
  double sum = 0.0;
  for (size_t c = 0; c < expected.size(); ++c) {
    if (!(expected[c] > 1e-3 * largest)) continue;  // an unlit room has no relative error
    const double error = got[c] / expected[c] - 1.0;
    r.worst = std::max(r.worst, std::abs(error)), sum += std::abs(error), ++r.counted;
    r.rooms.push_back({{"cell", partition.cells[c].name}, {"whole", expected[c]}, {"cells", got[c]}, {"error", error}});
  }
  r.mean = r.counted > 0 ? sum / r.counted : 0.0;
  return r;
}

// Both solves' options, checked before anything is printed.
SolveOptions solveOptions(const BenchCellsArgs& args) {
  SolveOptions o;
  o.projection = parseProjection(args.projection);
  o.resolution = args.resolution;
  o.until = 1.0;
  o.untilUnshot = args.untilUnshot;
  o.maxIterations = args.maxIterations;
  o.effects = EffectsMode::All;  // the same projection in every cell as in the whole building
  o.threads = 1;
  o.subdivide = parseSubdivide(args.subdivide);
  if (o.subdivide == Subdivide::Off && args.minElementM != 0.0)
    throw OptionError("--min-element shapes the elements, and --subdivide is off: add --subdivide uniform or adaptive, "
                      "or leave --min-element out");
  o.minElementM = args.minElementM;
  defaultMinElement(o, args.cellM);
  o.formFactorCacheBytes = formFactorCacheBytes(o.backend, args.cacheMb);
  validateOptions(o);
  checkPortalBins(args.portalBins);
  if (!(args.focusUnshot >= 0.0 && args.focusUnshot < 1.0))
    throw OptionError(fmt::format("--focus-unshot must be a fraction in [0, 1), e.g. 0.05; got {}", args.focusUnshot));
  return o;
}

nlohmann::json benchScene(const Scene& scene, const SolveOptions& o, const BenchCellsArgs& args) {
  const std::vector<Patch> patches = meshScene(scene, args.cellM);
  const CellPartition partition = findCells(scene, patches);
  if (args.focusCell < 0 || static_cast<size_t>(args.focusCell) >= partition.cells.size())  // before any solve
    throw OptionError(fmt::format("--focus-cell {} is not a cell of {}: give 0 to {}", args.focusCell, scene.source,
                                  partition.cells.size() - 1));
  fmt::print("\n{}: {} patches, {}, {}; {} {}, until {:g}% unshot, {} shots a cell a round on average, "
             "portal bins {}, {}{}\n",
             scene.source, patches.size(), counted(std::ssize(partition.cells), "cell"),
             counted(std::ssize(partition.portals), "portal"), args.projection,
             args.resolution, 100.0 * args.untilUnshot, args.exchangeShots, args.portalBins, benchCacheText(args.cacheMb),
             o.subdivide == Subdivide::Off ? ""
                                           : fmt::format("; {} elements, --min-element {:g}", args.subdivide,
                                                         args.minElementM));

  nlohmann::json result = {{"scene", scene.source},
                            {"patches", patches.size()},
                            {"cells", partition.cells.size()},
                            {"portals", partition.portals.size()}};
  fmt::print("{:<28} {:>10} {:>10} {:>11} {:>8}\n", "", "seconds", "wall s", "iterations", "unshot");
  if (args.focusOnly) {
    result.update(focusJson(printFocus(focusRun(scene, patches, partition, o, args), args)));
    return result;
  }
  std::vector<Rgb> wholeRadiosity;
  double wholeSeconds = 0.0;
  bool wholeReached = true;
  if (!args.skipWhole) {
    const double start = benchSeconds(1), wallStart = wallSeconds();
    ProgressiveSolver whole(scene, patches, o);
    while (!whole.done()) whole.step();
    wholeSeconds = benchSeconds(1) - start;
    wholeRadiosity = whole.radiosity();
    wholeReached = whole.ledger().unshotFraction() <= o.untilUnshot;
    fmt::print("{:<28} {:>10.3f} {:>10.3f} {:>11} {:>7.2f}%\n", "whole building, 1 thread", wholeSeconds,
               wallSeconds() - wallStart, iterationsText(static_cast<int>(whole.history().size()), wholeReached),
               100.0 * whole.ledger().unshotFraction());
    result.update({{"whole_seconds", wholeSeconds}, {"whole_iterations", whole.history().size()},
                   {"whole_reached", wholeReached}});
  }
  const CellsRun one = runCells(scene, patches, partition, o, args);
  const bool cellsReached = one.unshotFraction <= o.untilUnshot;
  fmt::print("{:<28} {:>10.3f} {:>10.3f} {:>11} {:>7.2f}%{}\n", "cells, 1 thread", one.seconds, one.wallSeconds,
             iterationsText(one.iterations, cellsReached), 100.0 * one.unshotFraction,
             args.skipWhole ? "" : "   " + speedText(wholeSeconds / one.seconds));
  if (!cellsReached || !wholeReached)
    fmt::print(stderr, "radmesh: warning: --max-iterations stopped a solve short of {:g}% unshot (+): its times "
               "and errors are not of the same light\n", 100.0 * o.untilUnshot);
  SolveOptions more = o;
  more.threads = ThreadPool::sizeFor(args.threads);
  const CellsRun parallel = runCells(scene, patches, partition, more, args);
  const bool identical = parallel.radiosity == one.radiosity;
  const std::string threads = counted(more.threads, "thread");
  fmt::print("{:<28} {:>10.3f} {:>10.3f} {:>11} {:>7.2f}%   {:.2f}x on {} (wall against wall), {}\n",
             "cells, " + threads, parallel.seconds, parallel.wallSeconds,
             iterationsText(parallel.iterations, parallel.unshotFraction <= o.untilUnshot),
             100.0 * parallel.unshotFraction, one.wallSeconds / parallel.wallSeconds, threads,
             identical ? "bitwise identical" : "DIFFERENT RESULTS");
  const FocusRun focus = printFocus(focusRun(scene, patches, partition, o, args), args);
  result.update({{"cells_seconds", one.seconds},
                 {"cells_wall_seconds", one.wallSeconds},
                 {"cells_iterations", one.iterations},
                 {"cells_rounds", one.rounds},
                 {"cells_elements", one.elements},
                 {"cells_reached", cellsReached},
                 {"cells_two_threads_seconds", parallel.seconds},
                 {"two_threads_speedup", one.wallSeconds / parallel.wallSeconds},
                 {"two_threads_identical", identical}});
  result.update(focusJson(focus));
  if (args.skipWhole) return result;
  const RoomErrors errors = roomErrors(scene, patches, partition, wholeRadiosity, one.radiosity);
  fmt::print("reflected light per room against the whole building: largest error {:.2f}%, mean {:.2f}% over {} lit "
             "rooms\n",
             100.0 * errors.worst, 100.0 * errors.mean, errors.counted);
  result.update({{"largest_room_error", errors.worst}, {"mean_room_error", errors.mean}, {"rooms", errors.rooms}});
  return result;
}

}  // namespace

nlohmann::json benchCells(const BenchCellsArgs& args) {
  const SolveOptions o = solveOptions(args);
  // Every scene read before the first is solved: a misspelt last one is found now, not after the rest.
  std::vector<Scene> loaded;
  for (const std::string& name : args.scenes) loaded.push_back(loadScene(name));
  fmt::print("seconds: on one thread, the solving thread's CPU time; on more, wall time; the speed-up on {} is wall "
             "time against wall time\n",
             counted(ThreadPool::sizeFor(args.threads), "thread"));
  nlohmann::json scenes = nlohmann::json::array();
  for (const Scene& scene : loaded) scenes.push_back(benchScene(scene, o, args));
  return {{"projection", args.projection}, {"resolution", args.resolution}, {"until_unshot", args.untilUnshot},
          {"subdivide", args.subdivide}, {"min_element", args.minElementM}, {"cache_mb", args.cacheMb},
          {"exchange_shots", args.exchangeShots}, {"portal_bins", args.portalBins},
          {"threads", ThreadPool::sizeFor(args.threads)}, {"scenes", scenes}};
}

}  // namespace radmesh::cli
