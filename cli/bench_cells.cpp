// `radmesh bench cells`: the cells solve beside the whole building's, side by side in one run.
#include <fmt/core.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "cli/bench.h"
#include "cli/bench_timing.h"
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
    weighted[c] += (b[j].r + b[j].g + b[j].b - e.r - e.g - e.b) * patches[j].areaM2;
    area[c] += patches[j].areaM2;
  }
  for (size_t c = 0; c < weighted.size(); ++c) weighted[c] = area[c] > 0.0 ? weighted[c] / area[c] : 0.0;
  return weighted;
}

struct CellsRun {
  double seconds = 0.0;
  int iterations = 0;
  int rounds = 0;
  double unshotFraction = 0.0;
  std::vector<Rgb> radiosity;
};

CellsRun runCells(const Scene& scene, const std::vector<Patch>& patches, const CellPartition& partition,
                  SolveOptions o, const BenchCellsArgs& args) {
  const double start = benchSeconds(o.threads);
  CellSolver solver(scene, patches, partition, o, {args.cellM, args.exchangeShots, args.portalBins});
  while (!solver.done()) solver.round();
  return {benchSeconds(o.threads) - start, solver.iterations(), solver.rounds(), solver.ledger().unshotFraction(),
          solver.radiosity()};
}

// The camera's cell first: seconds until its unshot power is at most focusUnshot of what it has
// had (emitted and arrived through portals), once light has reached it.
double focusSeconds(const Scene& scene, const std::vector<Patch>& patches, const CellPartition& partition,
                    const SolveOptions& o, const BenchCellsArgs& args, int& iterations) {
  const double start = benchSeconds(o.threads);
  CellSolver solver(scene, patches, partition, o, {args.cellM, args.exchangeShots, args.portalBins});
  if (args.focusCell < 0 || args.focusCell >= solver.cellCount())
    throw OptionError(fmt::format("--focus-cell {} is not a cell of {}: give 0 to {}", args.focusCell, scene.source,
                                  solver.cellCount() - 1));
  solver.focus(args.focusCell);
  auto reached = [&] {
    const Ledger& l = solver.cellSolver(args.focusCell).ledger();
    return l.input() > 0.0 && l.unshotFraction() <= args.focusUnshot;
  };
  while (!solver.done() && !(solver.rounds() > 0 && reached())) solver.round();
  iterations = solver.cellFigures()[args.focusCell].iterations;
  return benchSeconds(o.threads) - start;
}

nlohmann::json benchScene(const std::string& name, const BenchCellsArgs& args) {
  const Scene scene = loadScene(name);
  const std::vector<Patch> patches = meshScene(scene, args.cellM);
  const CellPartition partition = findCells(scene, patches);
  SolveOptions o;
  o.projection = parseProjection(args.projection);
  o.resolution = args.resolution;
  o.until = 1.0;
  o.untilUnshot = args.untilUnshot;
  o.maxIterations = args.maxIterations;
  o.effects = EffectsMode::All;  // the same projection in every cell as in the whole building
  o.threads = 1;
  validateOptions(o);
  fmt::print("\n{}: {} patches, {} cells, {} portals; {} {}, until {:g}% unshot, exchange every {} iterations, "
             "portal bins {}\n",
             scene.source, patches.size(), partition.cells.size(), partition.portals.size(), args.projection,
             args.resolution, 100.0 * args.untilUnshot, args.exchangeShots, args.portalBins);

  double start = benchSeconds(1);
  ProgressiveSolver whole(scene, patches, o);
  while (!whole.done()) whole.step();
  const double wholeSeconds = benchSeconds(1) - start;
  const CellsRun one = runCells(scene, patches, partition, o, args);
  SolveOptions two = o;
  two.threads = 2;
  const CellsRun parallel = runCells(scene, patches, partition, two, args);
  const bool identical = parallel.radiosity == one.radiosity;

  const std::vector<double> expected = reflectedPerCell(scene, patches, partition, whole.radiosity());
  const std::vector<double> got = reflectedPerCell(scene, patches, partition, one.radiosity);
  double largest = 0.0;
  for (double e : expected) largest = std::max(largest, e);
  nlohmann::json rooms = nlohmann::json::array();
  double worst = 0.0, sum = 0.0;
  int counted = 0;
  for (size_t c = 0; c < expected.size(); ++c) {
    if (!(expected[c] > 1e-3 * largest)) continue;  // an unlit room has no relative error
    const double error = got[c] / expected[c] - 1.0;
    worst = std::max(worst, std::abs(error)), sum += std::abs(error), ++counted;
    rooms.push_back({{"cell", partition.cells[c].name}, {"whole", expected[c]}, {"cells", got[c]}, {"error", error}});
  }
  int focusIterations = 0;
  const double focus = focusSeconds(scene, patches, partition, o, args, focusIterations);

  fmt::print("{:<28} {:>10} {:>11} {:>8}\n", "", "seconds", "iterations", "unshot");
  fmt::print("{:<28} {:>10.3f} {:>11} {:>7.2f}%\n", "whole building, 1 thread", wholeSeconds, whole.history().size(),
             100.0 * whole.ledger().unshotFraction());
  fmt::print("{:<28} {:>10.3f} {:>11} {:>7.2f}%   {:.1f}x faster\n", "cells, 1 thread", one.seconds, one.iterations,
             100.0 * one.unshotFraction, wholeSeconds / one.seconds);
  fmt::print("{:<28} {:>10.3f} {:>11} {:>7.2f}%   {:.2f}x on 2 threads (wall), {}\n", "cells, 2 threads",
             parallel.seconds, parallel.iterations, 100.0 * parallel.unshotFraction, one.seconds / parallel.seconds,
             identical ? "bitwise identical" : "DIFFERENT RESULTS");
  fmt::print("{:<28} {:>10.3f} {:>11}   cell {} to {:g}% of its light unshot\n", "focus cell first, 1 thread", focus,
             focusIterations, args.focusCell, 100.0 * args.focusUnshot);
  fmt::print("reflected light per room against the whole building: largest error {:.2f}%, mean {:.2f}% over {} lit "
             "rooms\n",
             100.0 * worst, counted > 0 ? 100.0 * sum / counted : 0.0, counted);
  return {{"scene", scene.source},
          {"patches", patches.size()},
          {"cells", partition.cells.size()},
          {"portals", partition.portals.size()},
          {"whole_seconds", wholeSeconds},
          {"whole_iterations", whole.history().size()},
          {"cells_seconds", one.seconds},
          {"cells_iterations", one.iterations},
          {"cells_rounds", one.rounds},
          {"cells_two_threads_seconds", parallel.seconds},
          {"two_threads_identical", identical},
          {"focus_cell", args.focusCell},
          {"focus_seconds", focus},
          {"focus_iterations", focusIterations},
          {"largest_room_error", worst},
          {"mean_room_error", counted > 0 ? sum / counted : 0.0},
          {"rooms", rooms}};
}

}  // namespace

nlohmann::json benchCells(const BenchCellsArgs& args) {
  fmt::print("times: one thread, the solving thread's CPU time; two threads, wall time\n");
  nlohmann::json scenes = nlohmann::json::array();
  for (const std::string& name : args.scenes) scenes.push_back(benchScene(name, args));
  return {{"projection", args.projection}, {"resolution", args.resolution}, {"until_unshot", args.untilUnshot},
          {"exchange_shots", args.exchangeShots}, {"portal_bins", args.portalBins}, {"scenes", scenes}};
}

}  // namespace radmesh::cli
