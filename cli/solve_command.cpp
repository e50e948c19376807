// `radmesh solve SCENE`: progressive refinement until --until, with progress, stats and a bake.
#include <fmt/core.h>

#include <algorithm>
#include <functional>
#include <memory>
#include <string>

#include "cli/option_checks.h"
#include "cli/cell_solve.h"
#include "cli/commands.h"
#include "cli/distributed_command.h"
#include "cli/scene_input.h"
#include "cli/effects_text.h"
#include "solver/radiosity/effects_plan.h"
#include "solver/io/output_path.h"
#include "cli/interrupt.h"
#include "cli/progress.h"
#include "cli/solve_flags.h"
#include "cli/stats_json.h"
#include "solver/bake/bake_reader.h"
#include "solver/bake/display_radiosity.h"
#include "solver/bake/gltf_export.h"
#include "solver/meshing/meshing.h"
#include "solver/projection/single_plane.h"
#include "solver/io/scene_loader.h"
#include "solver/radiosity/checkpoint.h"
#include "solver/scene/scene_error.h"

namespace radmesh::cli {

namespace {

struct SolveArgs {
  SolveFlags flags;
  std::string statsPath;
  std::string outPath;
  bool quiet = false;
  std::string checkpointPath;
  double checkpointEverySeconds = 0.0;  // 0: once, at the end
  std::string resumePath;
  bool distributed = false;
};

// "N patches", and their elements when patches are cut into elements.
std::string patchesText(const ProgressiveSolver& solver) {
  const std::string elements = solver.options().subdivide == Subdivide::Off
                                   ? "" : fmt::format(" ({} elements)", solver.elements().size());
  return fmt::format("{} patches{}", solver.patches().size(), elements);
}

// `resumedAt`: the iterations a checkpoint brought, which this run's seconds did not solve.
void printSummary(const ProgressiveSolver& solver, double seconds, size_t resumedAt) {
  const Ledger& l = solver.ledger();
  const size_t n = solver.history().size(), solved = n - resumedAt;
  const std::string resumed = resumedAt == 0 ? "" : fmt::format(" ({} after the checkpoint's {})", solved, resumedAt);
  fmt::print("solved: {}, {} iterations{}, convergence {:.2f}%, unshot {:.2f}%, {:.3f} s ({:.1f} it/s)\n",
             patchesText(solver), n, resumed, 100.0 * solver.convergence(), 100.0 * l.unshotFraction(), seconds,
             seconds > 0 ? solved / seconds : 0.0);
  if (const int cap = solver.options().maxIterations; resumedAt > 0 && resumedAt >= static_cast<size_t>(cap))
    fmt::print(stderr,
               "radmesh: warning: the checkpoint already holds {} iterations, at or past --max-iterations {} (which counts "
               "from the start of the solve): nothing more was solved; give --max-iterations above {} to go on\n",
               resumedAt, cap, resumedAt);
  double machineSeconds = 0.0;
  std::string machine;
  for (const IterationRecord& r : solver.history())
    if (r.shotStats) machineSeconds += r.shotStats->machineSeconds, machine = r.shotStats->machine;
  if (!machine.empty())
    fmt::print("{}: {:.3f} {} seconds ({:.3f} s per iteration) beside {:.3f} host seconds\n",
               toString(solver.options().backend), machineSeconds, machine, machineSeconds / std::max<size_t>(n, 1),
               seconds);
  fmt::print("ledger: emitted {:.6g} W = {} + unshot {:.6g} + not captured {:.6g} + escaped {:.6g}"
             "  (imbalance {:.1e})\n",
             l.emitted, absorbedTerm(l), l.unshot, l.notCaptured, l.escaped, l.imbalance());
  if (const std::string outside = lightOutsideSentence(l); !outside.empty()) fmt::print("        {}\n", outside);
  if (solver.options().formFactorCacheBytes == 0) return;
  // This run's shots alone: a checkpoint's were served (or not) by the cache of the run that shot them.
  size_t shots = 0, hits = 0;
  for (size_t i = resumedAt; i < n; ++i)
    shots += solver.history()[i].shooters.size(), hits += static_cast<size_t>(solver.history()[i].cacheHits);
  if (shots == 0) return;
  fmt::print("form-factor cache: {} of {}{} shots served without projecting (up to {:.0f} MiB; --cache-mb 0: none)\n",
             hits, resumedAt == 0 ? "" : "this run's ", shots, solver.options().formFactorCacheBytes / 1048576.0);
}

void writeBake(const std::string& path, const std::vector<Patch>& patches, const std::vector<Rgb>& displayRadiosity,
               int upAxis) {
  const DisplayMesh mesh = buildDisplayMesh(patches);
  writeBakeGlb(path, mesh, vertexRadiosity(mesh, displayRadiosity), upAxis);
  fmt::print("wrote {}\n", path);
}

// After Ctrl-C: the checkpoint written above, or the work lost, is said (stopAfterInterrupt).
[[noreturn]] void stopAfterInterrupt(const SolveArgs& args, const std::string& where) {
  cli::stopAfterInterrupt(where, args.checkpointPath, "give --checkpoint FILE to keep a solve's work");
}

// --cells auto: the rooms solved cell by cell. With `ranks`, this process's part of a distributed
// solve: process 0 alone writes (checkpoints too, every process's cells gathered).
void runCells(const SolveArgs& args, const Scene& scene, double cellM, const SolveOptions& options,
              CellRanks* ranks) {
  const bool writes = !ranks || ranks->rank() == 0;
  std::unique_ptr<CellSolver> solver = makeCellSolver(
      scene, meshScene(scene, cellM), options, {cellM, args.flags.exchangeShots, args.flags.portalBins}, ranks);
  if (!args.resumePath.empty()) {  // refused, if it must be, before anything is written
    resumeCellsFromCheckpoint(args.resumePath, scene, *solver);
    fmt::print("resumed from {} after round {} ({} iterations)\n", args.resumePath, solver->rounds(),
               solver->iterations());
  }
  const int resumedAt = solver->iterations();
  fmt::print("solving {} cell by cell: {} patches, {}, k={}, until {:g}% unshot\n", scene.source,
             solver->patches().size(), projectionText(options.projection, options.resolution), options.shooters,
             100.0 * options.untilUnshot);
  double lastCheckpoint = 0.0;
  const double seconds = solveCellsWithProgress(*solver, args.quiet, [&](double elapsed) {
    if (!(args.checkpointEverySeconds > 0.0)) return;
    bool due = elapsed - lastCheckpoint >= args.checkpointEverySeconds;
    if (ranks) due = ranks->firstSays(due);  // process 0's clock decides for all: all take part
    if (due) writeCellsCheckpoint(args.checkpointPath, scene, *solver), lastCheckpoint = elapsed;
  });
  if (!args.checkpointPath.empty()) {
    writeCellsCheckpoint(args.checkpointPath, scene, *solver);
    fmt::print("wrote checkpoint {}\n", args.checkpointPath);
  }
  if (interrupted()) stopAfterInterrupt(args, fmt::format("round {}", solver->rounds()));
  printCellsSummary(*solver, seconds);
  if (writes) warnAfterSolve(solver->ledger(), solver->options(), solver->iterations(), isClosed(scene));
  if (!args.statsPath.empty()) {
    nlohmann::json stats = cellsStats(*solver, scene.source, seconds, resumedAt);
    if (ranks) stats["distributed"] = distributedStats(*solver, ranks->traffic());
    if (writes) writeJson(args.statsPath, stats), fmt::print("wrote {}\n", args.statsPath);
  }
  if (args.outPath.empty()) return;
  solver->dropFormFactorCaches();  // the bake's gathering would otherwise come on top of them
  const Elements elements = solver->elements();  // every process gathers them together
  const std::vector<Rgb> radiosity = solver->displayElementRadiosity();
  if (writes) writeBake(args.outPath, elements.elements, radiosity, scene.upAxis);
}

void run(const SolveArgs& args, Processes* processes) {
  checkOutputPath("--stats", args.statsPath, ".json", "the stats are JSON");
  checkOutputPath("--out", args.outPath, ".glb", "a bake is glTF binary");
  checkOutputsDistinct(args.flags.scene,
                       {{"--out", args.outPath}, {"--stats", args.statsPath}, {"--checkpoint", args.checkpointPath}},
                       args.resumePath);
  // Process 0 writes the checkpoints (the others may run where the folder is not theirs).
  if (!args.checkpointPath.empty() && (!processes || processes->ranks.rank() == 0))
    checkCheckpointWritable(args.checkpointPath);
  // A distributed solve's processes would stop at different iterations, each waiting on the others.
  if (!processes) stopSolvesOnInterrupt();
  SolveOptions options = args.flags.resolved();
  if (readBake(args.flags.scene))  // else refused as a scene with no emitter
    throw SceneError(args.flags.scene, "", "is a bake, already solved: there is nothing to solve",
                     "walk it with radmesh-view, describe it with radmesh info, or draw it with radmesh render");
  const Scene scene = loadCommandScene(args.flags.scene, args.flags.strict, args.flags.daylight, args.flags.up,
                                       args.flags.metresPerUnit);
  checkAnalyticSeesNoShadows(scene, options.projection);
  const CellChoice cell = args.flags.announceCell(scene, options);
  if (args.flags.cellsOn()) return runCells(args, scene, cell.cellM, options, processes ? &processes->ranks : nullptr);
  if (processes) options.meshTransport = processes->meshMachine;
  const bool writes = !processes || processes->ranks.rank() == 0;
  ProgressiveSolver solver(scene, meshScene(scene, cell.cellM), options);
  if (!args.resumePath.empty()) {  // refused, if it must be, before anything is written
    resumeFromCheckpoint(args.resumePath, solver);
    fmt::print("resumed from {} after iteration {}\n", args.resumePath, solver.history().size());
  }
  const size_t resumedAt = solver.history().size();
  printEffects(solver.effectsPlan());
  if (solver.options().projection != options.projection)
    fmt::print("  occlusion is off, so --projection {} becomes {}\n", toString(options.projection),
               toString(solver.options().projection));
  options = solver.options();
  std::string until;
  if (options.until < 1.0) until = fmt::format("C={:.2f}", options.until);
  if (options.untilUnshot > 0.0)
    until += fmt::format("{}{:g}% unshot", until.empty() ? "" : " or ", 100.0 * options.untilUnshot);
  fmt::print("solving {}: {}, {}, k={}, until {}\n", scene.source, patchesText(solver),
             projectionText(options.projection, options.resolution), options.shooters, until.empty() ? "C=1" : until);
  const ProjectionSummary capture = solver.projectionSummary();
  if (options.projection != Projection::Analytic)
    fmt::print("projection catches {:.6f} of each shot (closed form), {:.6f} as the sum of its delta form factors\n",
               capture.capturedFraction, capture.deltaFormFactorSum);
  // The paper's ratio 3 loses 8 %: much below that, most of the light is counted lost, not bounced.
  const double papers = singlePlaneCapturedFraction(SolveOptions{}.ratio);
  if (capture.capturedFraction < papers)
    fmt::print(stderr,
               "radmesh: warning: the plane catches only {:.1f}% of each shot, and what it misses is lost (\"not "
               "captured\" in the ledger); --ratio 3, the paper's, catches {:.1f}%, and --projection hemicube all\n",
               100.0 * capture.capturedFraction, 100.0 * papers);

  double lastCheckpoint = 0.0;
  const double seconds = solveWithProgress(solver, args.quiet, [&](double elapsed) {
    if (args.checkpointEverySeconds > 0.0 && elapsed - lastCheckpoint >= args.checkpointEverySeconds) {
      if (writes) writeCheckpoint(args.checkpointPath, solver);
      lastCheckpoint = elapsed;
    }
  });
  if (!args.checkpointPath.empty() && writes) {
    writeCheckpoint(args.checkpointPath, solver);
    fmt::print("wrote checkpoint {}\n", args.checkpointPath);
  }
  if (interrupted()) stopAfterInterrupt(args, fmt::format("iteration {}", solver.history().size()));
  printSummary(solver, seconds, resumedAt);
  if (writes)
    warnAfterSolve(solver.ledger(), solver.options(), static_cast<long long>(solver.history().size()),
                   solver.effectsPlan().closed);

  if (!args.statsPath.empty()) {
    nlohmann::json stats = solveStats(solver, scene.source, seconds, resumedAt);
    if (processes) stats["distributed"] = processes->meshStats(solver);
    if (writes) writeJson(args.statsPath, stats), fmt::print("wrote {}\n", args.statsPath);
  }
  if (args.outPath.empty()) return;
  solver.dropFormFactorCache();
  if (writes) writeBake(args.outPath, solver.elements(), solver.displayElementRadiosity(), scene.upAxis);
}

// --distributed: every process of the mpirun runs the solve, each its own cells (CellSolver) or,
// with --backend mesh, its own block of the PE machine.
void runDistributed(const SolveArgs& args) {
  cli::runDistributed(args.flags.cellsOn(), args.flags.backend == "mesh",
                      [&](Processes& processes) { run(args, &processes); });
}

}  // namespace

void addSolveCommand(CLI::App& app) {
  auto args = std::make_shared<SolveArgs>();
  CLI::App* cmd = app.add_subcommand("solve", "Solve a scene by progressive refinement");
  addSolveFlags(cmd, args->flags);
  cmd->add_option("--stats", args->statsPath, "Write per-iteration figures and the energy ledger as JSON");
  cmd->add_option("--out", args->outPath, "Write the bake as glTF 2.0 binary (.glb) with COLOR_0 radiosity");
  cmd->add_flag("--quiet", args->quiet, "No progress lines");
  CLI::Option* checkpoint = cmd->add_option(
      "--checkpoint", args->checkpointPath, "Save the solver's state to this file at the end (resume with --resume)");
  cmd->add_option("--checkpoint-every", args->checkpointEverySeconds,
                  "Also save the checkpoint every this many seconds of solving")
      ->check(kPositive)
      ->needs(checkpoint);
  cmd->add_option("--resume", args->resumePath,
                  "Go on from a checkpoint of the same scene and options; --max-iterations counts from the start");
  cmd->add_flag("--distributed", args->distributed,
                "Under mpirun, with --cells auto: each process solves some of the cells, exchanging portal light "
                "with its neighbours (docs/cells.md); with --backend mesh: each process holds a block of the PE "
                "machine (docs/scaling.md); process 0 prints and writes");
  cmd->callback([args] { args->distributed ? runDistributed(*args) : run(*args, nullptr); });
}

}  // namespace radmesh::cli
