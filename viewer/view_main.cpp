// radmesh-view [SCENE]: walk through a scene while its radiosity converges.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "cli/option_checks.h"
#include "cli/usage_failure.h"
#include "cli/scene_input.h"
#include "cli/solve_flags.h"
#include "cli/view_flags.h"
#include "solver/io/output_path.h"
#include "solver/meshing/meshing.h"
#include "solver/radiosity/cell_solver.h"
#include "solver/radiosity/checkpoint.h"
#include "solver/scene/scene_error.h"
#include "solver/scene/sun.h"
#include "solver/scene/units.h"
#include "viewer/panel.h"
#include "viewer/viewer_app.h"

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);  // a line at a time into a pipe or a file too
  if (const std::string option = radmesh::cli::optionWithEmptyValue(argc, argv); !option.empty()) {
    std::fprintf(stderr, "radmesh-view: error: %s is given an empty value: give it a value, or leave it out\n",
                 option.c_str());
    return 2;
  }
  radmesh::ViewerArgs args;
  std::string units;
  std::string backend = "mesh", projection = "plane", mapping = "hierarchical", effects = "auto", size = "1280x720", panel = "progress",
              subdivide = "off";
  radmesh::SolveOptions& o = args.setup.options;
  CLI::App app{"radmesh-view: walk through a scene while its radiosity converges"};
  app.failure_message(radmesh::cli::usageFailure("radmesh-view"));
  app.add_option("scene", args.scene, "Built-in name (office, cornell, furnace, two-rooms, building:COLSxROWS), a .gltf/.glb/.mgf file, or a bake to walk")
      ->capture_default_str();
  radmesh::cli::addUpOption(&app, args.up);
  app.add_option("--units", units, radmesh::cli::kUnitsHelp);
  app.add_flag("--strict", args.strict, std::string(radmesh::cli::kStrictHelp) + ", as radmesh solve's; files opened later too");
  CLI::Option* backendGiven =
      app.add_option("--backend", backend, "mesh (emulated MasPar MP-1, the default here; native with --cells auto) or "
                     "native (host CPU)")
          ->type_name("mesh|native")
          ->capture_default_str();
  app.add_option("--projection", projection, "plane, hemicube or analytic")
      ->type_name("plane|hemicube|analytic")
      ->capture_default_str();
  app.add_option("--mapping", mapping, "Single plane over the PEs (mesh back end): hierarchical, cut-and-stack, adaptive")
      ->type_name("hierarchical|cut-and-stack|adaptive")
      ->capture_default_str();
  app.add_option("--effects", effects, "auto: simulate only what the scene calls for; all: everything")
      ->type_name("auto|all")
      ->capture_default_str();
  app.add_option("--subdivide", subdivide, "off; uniform: patches shoot, their elements receive and are shown; adaptive: elements split where the light changes (docs/accuracy.md)")
      ->type_name("off|uniform|adaptive")
      ->capture_default_str();
  CLI::Option* minElement = app.add_option("--min-element", o.minElementM, "With --subdivide uniform: longest element edge, metres (0: four a patch); with adaptive: the smallest split (0: a quarter of the cell)")
      ->capture_default_str();
  app.add_option_function<std::string>(
      "--pe-grid", [&o](const std::string& text) { radmesh::parsePeGrid(text, o.machine); },
      "Mesh backend: the emulated machine's PE columns x rows, powers of two (default 64x64, the MP-1's)");
  app.add_option("--pe-memory", o.machine.memoryKb, "Mesh backend: each PE's memory in KB (the MP-1's 16)")
      ->capture_default_str();
  app.add_option("--resolution", o.resolution, "N for an N x N projection plane, 16..2048")->capture_default_str();
  app.add_option("--ratio", o.ratio, radmesh::cli::kRatioHelp)->capture_default_str();
  app.add_option("--shooters", o.shooters, "k patches shot per iteration")->capture_default_str();
  radmesh::Preset preset = radmesh::Preset::Bake;
  CLI::Option* presetGiven =
      app.add_option_function<std::string>(
             "--preset",
             [&](const std::string& name) {
               preset = radmesh::parsePreset(name);
               radmesh::applyPreset(preset, o);
               projection = radmesh::toString(o.projection);
               subdivide = radmesh::toString(o.subdivide);
               // The hemicube runs on the host; the paper's plane stays on the emulated machine.
               backend = preset == radmesh::Preset::Paper ? "mesh" : "native";
             },
             "bake (hemicube 256 on the host), paper (single plane 128 on the emulated MP-1, to C = 0.95) or "
             "elements (the bake, but patches 2.625 x the cell shoot and elements a quarter of theirs receive), as radmesh solve's; "
             "flags given beside it win")
          ->trigger_on_parse();
  CLI::Option* cell =
      app.add_option("--cell", args.setup.cellM, "Grid cell size for meshing, metres (default: from the scene's size)");
  CLI::Option* sky = app.add_option("--sky", args.daylight.skyLux,
                                    "Light the scene by a sky of this horizontal illuminance (lux) through its openings");
  std::string skyModel = "uniform";
  app.add_option("--sky-model", skyModel, "The sky's luminance: uniform or cie-overcast")
      ->capture_default_str()
      ->needs(sky);  // without a sky it would shape nothing, without a word
  std::string sun;
  app.add_option("--sun", sun, "Sunlight: AZIMUTH,ELEVATION[,LUX], degrees clockwise from north and above the horizon");
  app.add_option("--until", o.until, "Stop at this convergence C (0..1]; 1: on the unshot power alone")
      ->capture_default_str();
  app.add_option("--until-unshot", o.untilUnshot, radmesh::cli::kUntilUnshotHelp)
      ->capture_default_str();
  app.add_option("--max-iterations", o.maxIterations,
                 std::string(radmesh::cli::kMaxIterationsHelp) + "; the panel's Step and --steps go past it")
      ->capture_default_str();
  std::string cells = "off";
  app.add_option("--cells", cells, "auto: find the rooms and solve them cell by cell, the camera's first (docs/cells.md); "
                 "off: the whole scene at once")
      ->type_name("auto|off")
      ->capture_default_str();
  radmesh::cli::addPortalExchangeOptions(&app, args.setup.exchangeShots, args.setup.portalBins);
  app.add_option("--threads", o.threads, "Host threads of the solve (0: every core but one, left to drawing, which "
                 "llvmpipe does on the CPU too)")
      ->transform(radmesh::cli::threadCount("radmesh-view"))
      ->capture_default_str();
  std::optional<double> cacheMb;
  app.add_option("--cache-mb", cacheMb, radmesh::cli::kCacheMbHelp);
  app.add_option("--resume", args.resume, "Go on from a checkpoint of the same scene and options (radmesh solve "
                 "--checkpoint, or the panel's Save checkpoint)");
  CLI::Option* checkpointGiven =
      app.add_option("--checkpoint", args.checkpoint, "Where the panel's Save checkpoint (F5) writes")
          ->capture_default_str();
  radmesh::cli::addViewFlags(&app, args.start, args.exposureEv);
  app.add_option("--size", size, "Window size WxH")->capture_default_str();
  app.add_option("--panel", panel, "Panel tab shown first: progress, item-buffer, parameters, scene, view")
      ->capture_default_str();
  app.add_option("--steps", args.steps, "Smoke test: take N steps, as the panel's Step does (an iteration; with "
                 "--cells auto a round: every cell's shots and a portal exchange; none for a bake), save "
                 "--screenshot, exit")
      ->check(radmesh::cli::kPositive);
  app.add_option("--min-frames", args.minFrames, "With --steps: draw at least this many frames (timing)")
      ->check(radmesh::cli::kNonNegative);
  app.add_option("--frames", args.frames, "Frame-time report: solve while drawing N frames once the mesh shows, "
                 "print the lowest and median frame rates, save --screenshot, exit")
      ->check(radmesh::cli::kPositive);
  app.add_option("--screenshot", args.screenshot, "PNG of the whole window (with --steps or --frames)");
  app.add_flag("--quiet", args.quiet, "No frame statistics on exit (it prints no progress lines while it runs)");
  try {
    try {
      std::vector<std::string> arguments = radmesh::cli::decimalArguments(app, argc, argv);
      app.parse(arguments);  // an option's own check throws OptionError while parsing
    } catch (const CLI::ParseError& e) {
      // CLI11 prints the message (or the help); every usage error exits 2, as radmesh's do.
      return app.exit(e) == 0 ? 0 : 2;
    }
    args.cellGiven = cell->count() > 0;
    if (args.cellGiven) radmesh::checkCell(args.setup.cellM);  // before the window, as the other options
    args.elementsPreset = presetGiven->count() > 0 && preset == radmesh::Preset::Elements && minElement->count() == 0;
    if (sky->count() > 0) radmesh::checkSkyLux(args.daylight.skyLux);
    args.daylight.sky = radmesh::parseSkyModel(skyModel);
    if (!sun.empty()) args.daylight.sun = {radmesh::parseSun(sun)};
    if (!args.screenshot.empty() && args.steps <= 0 && args.frames <= 0)
      throw radmesh::OptionError("--screenshot needs --steps N (the steps to take first) or --frames N");
    if (args.steps > 0 && args.frames > 0)
      throw radmesh::OptionError("--steps and --frames are two different runs: give one");
    // Before the window opens and the solve runs, not after.
    radmesh::checkOutputPath("--screenshot", args.screenshot, ".png", "the screenshot is PNG");
    radmesh::checkOutputsDistinct(args.scene, {{"--screenshot", args.screenshot}, {"--checkpoint", args.checkpoint}},
                                  args.resume);
    // As radmesh solve does: a save hours later to a folder that does not exist is found now. The
    // default, beside where it runs, is left to the panel, where it can be changed.
    if (checkpointGiven->count() > 0) radmesh::checkCheckpointWritable(args.checkpoint);
    args.setup.cells = radmesh::parseCells(cells);
    radmesh::checkPortalBins(args.setup.portalBins);
    // The cells solve runs on the host's CPU (docs/cells.md).
    if (args.setup.cells && backendGiven->count() == 0) backend = "native";
    // The panel takes its own width beside the 3D view; X refuses windows past 16384.
    const int narrowest = static_cast<int>(radmesh::Panel::kWidthPx) + 64;
    const auto window = radmesh::cli::parseSize(size, 64, 16384);
    if (!window || (*window)[0] < narrowest)
      throw radmesh::OptionError("--size '" + size + "' is not WxH with a width of " + std::to_string(narrowest) +
                                 " to 16384 (the panel's " + std::to_string(int(radmesh::Panel::kWidthPx)) +
                                 " beside the view) and a height of 64 to 16384, e.g. 1280x720");
    args.windowSize = {(*window)[0], (*window)[1]};
    args.firstTab = radmesh::parsePanelTab(panel);
    if (!units.empty()) args.metresPerUnit = radmesh::parseUnits(units);
    o.backend = radmesh::parseBackend(backend);
    o.projection = radmesh::parseProjection(projection);
    o.mapping = radmesh::parseMapping(mapping);
    o.effects = radmesh::parseEffects(effects);
    o.subdivide = radmesh::parseSubdivide(subdivide);
    // Each start sizes the cache for the back end it runs on (viewer/solver_run.cpp).
    if (cacheMb) args.setup.cacheMb = radmesh::checkedCacheMb(*cacheMb);
    std::vector<std::string> given;
    for (const CLI::Option* option : app.get_options())
      if (option->count() > 0) given.push_back(option->get_name());
    radmesh::refuseFlagsThatShapeNothing(given, o, args.setup.cells);
    for (const std::string& flag : given)  // what walking a bake takes, and the bake itself; the rest shapes a solve
      if (flag != "scene" && flag != "--up" && flag != "--size" && flag != "--panel" && flag != "--steps" &&
          flag != "--frames" && flag != "--min-frames" && flag != "--screenshot" && flag != "--camera" &&
          flag != "--look" && flag != "--exposure" && flag != "--quiet")
        args.solveFlags.push_back(flag);
    if (args.minFrames > 0 && args.steps <= 0)
      throw radmesh::OptionError("--min-frames times a --steps run: add --steps N, or leave --min-frames out");
    radmesh::validateOptions(o);
    return radmesh::runViewer(args);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "radmesh-view: error: %s\n", e.what());
    return 2;
  }
}
