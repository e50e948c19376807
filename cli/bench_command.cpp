// `radmesh bench ...`: measured tables (and JSON) of what the solver's choices cost.
#include <fmt/core.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string_view>
#include <vector>

#include "cli/option_checks.h"
#include "cli/bench.h"
#include "cli/scene_input.h"
#include "cli/commands.h"
#include "cli/distributed_command.h"
#include "solver/scene/scene_error.h"
#include "solver/io/output_path.h"
#include "cli/solve_flags.h"
#include "cli/stats_json.h"

namespace radmesh::cli {

namespace {

// Before the run, as every output: its folder must exist (solver/io/output_path.h).
void checkJsonOutput(const std::string& path) { checkOutputPath("--json", path, ".json", "the figures are JSON"); }

void writeJsonIfAsked(const std::string& path, const nlohmann::json& result) {
  if (!path.empty()) writeJson(path, result), fmt::print("wrote {}\n", path);
}

// A value listed twice (--resolutions 16,16) would be measured twice, as two rows of one setting.
template <typename T>
void dropRepeats(std::vector<T>& list) {
  std::vector<T> kept;
  for (const T& value : list)
    if (std::ranges::find(kept, value) == kept.end()) kept.push_back(value);
  list = std::move(kept);
}

void addCacheOption(CLI::App* cmd, double& mb) {
  cmd->add_option_function<double>(
      "--cache-mb",
      [&mb](double given) { mb = checkedCacheMb(given); },
      kBenchCacheMbHelp);
}

void addBenchSolve(CLI::App* bench) {
  auto args = std::make_shared<BenchSolveArgs>();
  auto json = std::make_shared<std::string>();
  CLI::App* cmd = bench->add_subcommand("solve", "Time per iteration and to convergence by projection and resolution");
  cmd->add_option("scene", args->scene, "Scene name or file")->capture_default_str();
  addUpOption(cmd, args->up);
  addUnitsOption(cmd, args->metresPerUnit);
  cmd->add_option("--cell", args->cellM, "Grid cell size, metres (default: chosen from the scene's size)");
  addDaylightFlags(cmd, args->daylight);
  cmd->add_option("--projections", args->projections, "Projections to time")->delimiter(',')->capture_default_str();
  cmd->add_option("--resolutions", args->resolutions, "Resolutions N to time")->delimiter(',')->capture_default_str();
  cmd->add_option("--shooters", args->shooters, "Shooters k per iteration to time")->delimiter(',')->capture_default_str();
  cmd->add_option("--backend", args->backend, "native or mesh (emulated MP-1)")
      ->type_name("native|mesh")
      ->capture_default_str();
  addMachineFlags(cmd, args->machine);
  cmd->add_option("--until", args->until, "Convergence to time to")->capture_default_str();
  cmd->add_option("--until-unshot", args->untilUnshot, "Or the unshot fraction to time to (0: none)")->capture_default_str();
  cmd->add_option("--max-iterations", args->maxIterations, "Cap per run")->capture_default_str();
  cmd->add_option("--cells", args->cellsMode, "auto: time the cells solve (with --until 1 --until-unshot F); off")
      ->type_name("auto|off")
      ->capture_default_str();
  addPortalExchangeOptions(cmd, args->exchangeShots, args->portalBins);
  cmd->add_option("--threads", args->threads, "Host threads (0: every core)")->transform(threadCount("radmesh"))->capture_default_str();
  addCacheOption(cmd, args->cacheMb);
  // A list of cell sizes, named as bench accuracy's --cell-sizes; its first name, --scaling-cells, kept as an alias.
  cmd->add_option("--scaling-cell-sizes,--scaling-cells", args->cells,
                  "Grid cell sizes, metres, of the patch-count sweep (a list)")
      ->delimiter(',');
  cmd->add_option("--scaling-resolution", args->scalingResolution, "Plane resolution of the sweep")->capture_default_str();
  cmd->add_option("--json", *json, "Also write the figures as JSON");
  cmd->add_flag("--distributed", args->distributed,
                "With --cells auto, under mpirun: the cells solve over the processes, with each rank's work, "
                "messages, bytes and MPI wait and the model on more ranks (docs/scaling.md); rank 0 prints and writes");
  cmd->add_option("--csv", args->csvStem, "With --distributed: write STEM-ranks.csv and STEM-model.csv");
  cmd->callback([args, json, cmd] {
    checkJsonOutput(*json);
    checkOutputPath("--csv", args->csvStem, "", "");  // STEM-ranks.csv and STEM-model.csv go beside it
    args->cellGiven = cmd->count("--cell") > 0;
    args->projectionsGiven = cmd->count("--projections") > 0;
    // Flags for what this run does not time would be dropped without a word.
    for (const char* flag : {"--pe-grid", "--pe-memory"})
      if (cmd->count(flag) > 0 && parseBackend(args->backend) != Backend::Mesh)
        throw OptionError(fmt::format("bench solve {} shapes the emulated machine: add --backend mesh, or leave {} out",
                                      flag, flag));
    if (cmd->count("--scaling-resolution") > 0 && args->cells.empty())
      throw OptionError("bench solve --scaling-resolution is the resolution of the --scaling-cell-sizes sweep: give "
                        "--scaling-cell-sizes too, or leave it out");
    dropRepeats(args->projections), dropRepeats(args->resolutions), dropRepeats(args->shooters), dropRepeats(args->cells);
    if (!args->distributed) return writeJsonIfAsked(*json, benchSolve(*args));
    if (!parseCells(args->cellsMode))
      throw OptionError("bench solve --distributed measures a cells solve over processes: give --cells auto");
    runDistributed(true, false, [&](Processes& processes) {
      const nlohmann::json result = benchSolve(*args, &processes.ranks);
      if (processes.ranks.rank() == 0) writeJsonIfAsked(*json, result);
    });
  });
}

void addBenchAccuracy(CLI::App* bench) {
  auto args = std::make_shared<AccuracyArgs>();
  auto quick = std::make_shared<bool>(false);
  auto json = std::make_shared<std::string>();
  CLI::App* cmd = bench->add_subcommand("accuracy", "Error against a reference by projection, resolution and cell size");
  cmd->add_option("scene", args->scene, "Scene name or file")->capture_default_str();
  addUpOption(cmd, args->up);
  addUnitsOption(cmd, args->metresPerUnit);
  cmd->add_option("--name", args->name, "File stem of the outputs (default: the scene's)")->check(kFileStem);
  cmd->add_option("--out-dir", args->outDir, "Write the CSV (NAME.csv, NAME-traces.csv) and the PNG plots here");
  cmd->add_option("--json", *json, "Also write every figure, with the traces of every iteration, as JSON");
  addDaylightFlags(cmd, args->daylight);
  // Its first name, --cells, is the visibility cells' auto|off on the solving commands: kept as an alias.
  cmd->add_option("--cell-sizes,--cells", args->cells,
                  "Grid cell sizes to sweep, metres: --cell's, a list (default: these for a room-sized model, scaled "
                  "to the cell the scene's solve chooses)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--resolutions", args->resolutions, "Resolutions N")->delimiter(',')->capture_default_str();
  cmd->add_option("--reference-resolution", args->referenceResolution, "Hemicube N of the reference")->capture_default_str();
  cmd->add_option("--reference-cell", args->referenceCellM,
                  "Cell, metres, of the pictures' reference: a patch mesh finer than any of --cell-sizes, solved but not "
                  "swept (0: the finest of --cell-sizes)")
      ->capture_default_str();
  cmd->add_option("--reference-until", args->referenceUntil, "Convergence C of the reference")->capture_default_str();
  // Named as --until-unshot, beside --reference-until; its first name, --reference-unshot, kept as an alias.
  cmd->add_option("--reference-until-unshot,--reference-unshot", args->referenceUnshot,
                  "And the most unshot power the reference may leave, as a fraction of the emitted")
      ->capture_default_str();
  cmd->add_option("--max-iterations", args->maxIterations, "Cap per timed solve; a reference may take ten times as many")
      ->check(kPositive)
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "Host threads of the reference solves (0: every core); the sweep is timed on one")
      ->transform(threadCount("radmesh"))
      ->capture_default_str();
  cmd->add_option("--projections", args->projections, "Projections: plane (ratios 3 and 5), hemicube")
      ->delimiter(',')->capture_default_str();
  cmd->add_option("--subdivide", args->subdivide,
                  "Receivers to compare: off (patches), uniform, adaptive (elements; docs/accuracy.md)")
      ->delimiter(',')->capture_default_str();
  cmd->add_option("--min-element", args->minElements,
                  "Element sizes, metres, for uniform (0: four a patch) and adaptive (0: a quarter of the cell)")
      ->delimiter(',')->capture_default_str();
  cmd->add_option("--adaptive-min-element", args->adaptiveMinElements,
                  "Element sizes, metres, for adaptive instead of --min-element")->delimiter(',');
  cmd->add_option("--split-contrast", args->splitContrast, "With adaptive: the split threshold")->capture_default_str();
  cmd->add_option("--element-rows", args->elementRows,
                  "Element rows for uniform and adaptive, each measured: auto, share, rasterise (the solve's --element-rows)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--subdivide-cells", args->subdivideCells,
                  "The cell sizes (of --cell-sizes) uniform and adaptive run on (default: the coarsest)")->delimiter(',');
  cmd->add_option("--until-unshot", args->untilUnshot,
                  "Also solve each point on to this unshot fraction and measure it there (0: C = 0.99 only)")
      ->capture_default_str();
  addCacheOption(cmd, args->cacheMb);
  cmd->add_flag("--quick", *quick, "A sweep that finishes in under a minute (for CI)");
  cmd->callback([args, quick, json, cmd] {
    checkJsonOutput(*json);
    // What --quick sets would replace what was given without a word.
    for (const char* flag : {"--resolutions", "--reference-resolution", "--reference-until", "--reference-until-unshot"})
      if (*quick && cmd->count(flag) > 0)
        throw OptionError(fmt::format("bench accuracy --quick sets {} itself (docs/accuracy.md): leave {} out, or "
                                      "drop --quick", flag, flag));
    if (*quick && args->cells.size() > 2 && cmd->count("--cell-sizes") > 0)
      throw OptionError("bench accuracy --quick sweeps at most two --cell-sizes: give two, or drop --quick");
    AccuracyArgs a = *quick ? quickAccuracyArgs(*args) : *args;
    a.cellsGiven = cmd->count("--cell-sizes") > 0;
    dropRepeats(a.cells), dropRepeats(a.resolutions), dropRepeats(a.projections), dropRepeats(a.subdivide);
    dropRepeats(a.minElements), dropRepeats(a.adaptiveMinElements), dropRepeats(a.subdivideCells);
    dropRepeats(a.elementRows);
    // A flag that shapes receivers the sweep does not measure would be dropped without a word.
    const auto measured = [&a](const char* mode) { return std::ranges::find(a.subdivide, mode) != a.subdivide.end(); };
    for (const char* flag : {"--min-element", "--element-rows", "--subdivide-cells", "--adaptive-min-element",
                             "--split-contrast"}) {
      const bool adaptiveOnly = flag == std::string_view("--adaptive-min-element") || flag == std::string_view("--split-contrast");
      const char* needed = adaptiveOnly ? "adaptive" : "uniform or adaptive";
      if (cmd->count(flag) > 0 && !measured("adaptive") && (adaptiveOnly || !measured("uniform")))
        throw OptionError(fmt::format("bench accuracy {} shapes {} elements, and --subdivide does not measure them: add "
                                      "{} to --subdivide, or leave {} out",
                                      flag, adaptiveOnly ? "adaptive" : "the", needed, flag));
    }
    if (cmd->count("--name") == 0) a.name = std::filesystem::path(a.scene).stem().string();
    writeJsonIfAsked(*json, benchAccuracy(a));
  });
}

void addBenchCells(CLI::App* bench) {
  auto args = std::make_shared<BenchCellsArgs>();
  auto json = std::make_shared<std::string>();
  CLI::App* cmd = bench->add_subcommand("cells", "The cells solve beside the whole building's: time and error per room");
  cmd->add_option("scenes", args->scenes, "Scenes (names or files)")->capture_default_str();
  cmd->add_option("--cell", args->cellM, "Grid cell size, metres")->capture_default_str();
  cmd->add_option("--projection", args->projection, "plane, hemicube or analytic")
      ->type_name("plane|hemicube|analytic")
      ->capture_default_str();
  cmd->add_option("--resolution", args->resolution, "N of the projection")->capture_default_str();
  cmd->add_option("--until-unshot", args->untilUnshot, "Both solves stop at this unshot fraction")->capture_default_str();
  addPortalExchangeOptions(cmd, args->exchangeShots, args->portalBins);
  cmd->add_option("--focus-cell", args->focusCell, "The camera's cell, solved first")->capture_default_str();
  cmd->add_option("--focus-unshot", args->focusUnshot, "The focus cell's unshot fraction to time to")->capture_default_str();
  cmd->add_option("--max-iterations", args->maxIterations, "Cap per solve")->capture_default_str();
  cmd->add_option("--subdivide", args->subdivide, "Both solves' receivers: off (patches), uniform or adaptive elements")
      ->type_name("off|uniform|adaptive")
      ->capture_default_str();
  cmd->add_option("--min-element", args->minElementM, "With --subdivide: the longest element edge, metres")
      ->capture_default_str();
  addCacheOption(cmd, args->cacheMb);
  CLI::Option* threads =
      cmd->add_option("--threads", args->threads,
                      "Host threads of the second cells solve (0: every core), beside the first on one; the whole "
                      "building's and the focus run are on one")
          ->transform(threadCount("radmesh"))
          ->capture_default_str();
  cmd->add_flag("--skip-whole", args->skipWhole, "No whole-building solve (for buildings where it takes too long)");
  cmd->add_flag("--focus-only", args->focusOnly, "Only the focus cell's time to --focus-unshot (no solve to --until-unshot)");
  cmd->add_option("--json", *json, "Also write the figures as JSON");
  cmd->callback([args, json, threads] {
    checkJsonOutput(*json);
    if (args->focusOnly && threads->count() > 0)
      throw OptionError("bench cells --threads sets the second cells solve's threads, and --focus-only runs the focus "
                        "cell alone, on one: leave --threads out, or drop --focus-only");
    writeJsonIfAsked(*json, benchCells(*args));
  });
}

}  // namespace

void addBenchCommand(CLI::App& app) {
  CLI::App* bench = app.add_subcommand("bench", "Measure what accuracy costs in time");
  bench->require_subcommand(1);
  addBenchSolve(bench);
  addBenchAccuracy(bench);
  addBenchCells(bench);
}

}  // namespace radmesh::cli
