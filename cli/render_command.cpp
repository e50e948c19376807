// `radmesh render SCENE|FILE.glb --out FILE.png`: solve (or read a bake) and draw one view through
// OSMesa, with the window's renderer and no display.
#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "cli/option_checks.h"
#include "cli/commands.h"
#include "cli/scene_input.h"
#include "solver/radiosity/effects_plan.h"
#include "solver/scene/scene_error.h"

#if RADMESH_HAS_VIEWER
#include "cli/cell_solve.h"
#include "cli/effects_text.h"
#include "cli/interrupt.h"
#include "solver/io/output_path.h"
#include "cli/progress.h"
#include "cli/solve_flags.h"
#include "solver/bake/bake_reader.h"
#include "solver/bake/display_radiosity.h"
#include "solver/meshing/meshing.h"
#include "solver/io/scene_loader.h"
#include "viewer/camera.h"
#include "viewer/exposure.h"
#include "viewer/offscreen_render.h"
#include "cli/view_flags.h"
#endif

namespace radmesh::cli {

#if RADMESH_HAS_VIEWER

namespace {

struct RenderArgs {
  SolveFlags flags;
  ViewStart start;  // --camera, --look
  double fovDeg = 60.0;
  std::string size = "1024x768";
  int iterations = 0;  // 0: until --until
  std::optional<double> exposureEv;
  int frames = 1;
  bool quiet = false;
  std::string outPath;
};

// Drawing takes about this much a pixel at its peak (OSMesa's colour and depth, the captured
// picture, the PNG's rows; measured with /usr/bin/time at 4096x4096: 20.3 bytes).
constexpr double kRenderBytesPerPixel = 21.0;

glm::ivec2 pictureSize(const std::string& text, std::size_t memoryBytes) {
  const auto size = parseSize(text, 1, 16384);
  if (!size) throw OptionError(fmt::format("--size '{}' is not WxH with each side in 1..16384 (e.g. 1024x768)", text));
  // A picture the machine cannot hold would be killed or thrown out part way, after the solve.
  const double needed = kRenderBytesPerPixel * (*size)[0] * (*size)[1];
  if (memoryBytes > 0 && needed > 0.5 * static_cast<double>(memoryBytes)) {
    const int side = static_cast<int>(std::sqrt(0.5 * static_cast<double>(memoryBytes) / kRenderBytesPerPixel));
    throw OptionError(fmt::format("--size {}: drawing it needs about {:.1f} GB, more than half of the {:.1f} GB of "
                                  "memory this process may use: give a smaller size (at most about {}x{})",
                                  text, needed / 1e9, static_cast<double>(memoryBytes) / 1e9, side, side));
  }
  return {(*size)[0], (*size)[1]};
}

constexpr double kMinFovDeg = 0.01;
// At 178 degrees a 1 m box showed black bands down both sides of the picture; 170 shows none.
constexpr double kMaxFovDeg = 170.0;

// The start view of the walkthrough, moved by --camera / --look / --fov: chosen (or refused) from
// the scene's frame before a solve, not after it.
RenderView chooseView(const RenderArgs& args, const SceneFrame& frame) {
  WalkCamera walk(frame);
  walk.fovYDeg = args.fovDeg;
  walk.startFrom(args.start, args.fovDeg != RenderArgs{}.fovDeg);
  return walk.view();
}

struct Solved {
  DisplayMesh mesh;
  std::vector<Rgb> vertexB;
  RenderView view;
};

// What an interrupted render says was lost: it keeps no checkpoint of its own.
constexpr const char* kRenderKeepsNothing =
    "no picture is drawn of a solve cut short; to keep a long solve's work: radmesh solve SCENE --checkpoint FILE "
    "--out BAKE.glb, then render the bake";

Solved solveScene(const RenderArgs& args) {
  stopSolvesOnInterrupt();  // Ctrl-C stops the solve as solve's does, and says so (not a bake's drawing)
  SolveOptions options = args.flags.resolved();
  if (args.iterations > 0) {
    options.until = 1.0;  // C never passes 1 and the unshot rule is off: only the count stops the solve
    options.untilUnshot = 0.0;
    options.maxIterations = args.iterations;
  }
  const Scene scene = loadCommandScene(args.flags.scene, args.flags.strict, args.flags.daylight, args.flags.up,
                                       args.flags.metresPerUnit);
  checkAnalyticSeesNoShadows(scene, options.projection);
  const RenderView view = chooseView(args, sceneFrame(scene));
  const CellChoice cell = args.flags.announceCell(scene, options);
  auto solvedFrom = [&](const std::vector<Patch>& patches, const std::vector<Rgb>& displayRadiosity) {
    Solved solved{buildDisplayMesh(patches), {}, view};
    solved.vertexB = vertexRadiosity(solved.mesh, displayRadiosity);
    return solved;
  };
  if (args.flags.cellsOn()) {
    std::unique_ptr<CellSolver> solver =
        makeCellSolver(scene, meshScene(scene, cell.cellM), options, {cell.cellM, args.flags.exchangeShots, args.flags.portalBins});
    const double seconds = solveCellsWithProgress(*solver, args.quiet);
    if (interrupted()) stopAfterInterrupt(fmt::format("round {}", solver->rounds()), "", kRenderKeepsNothing);
    printCellsSummary(*solver, seconds);
    warnAfterSolve(solver->ledger(), solver->options(), solver->iterations(), isClosed(scene), args.iterations > 0);
    return solvedFrom(solver->elements().elements, solver->displayElementRadiosity());
  }
  ProgressiveSolver solver(scene, meshScene(scene, cell.cellM), options);
  printEffects(solver.effectsPlan());
  solveWithProgress(solver, args.quiet);
  if (interrupted()) stopAfterInterrupt(fmt::format("iteration {}", solver.history().size()), "", kRenderKeepsNothing);
  fmt::print("solved {}: {} patches, {} iterations, C = {:.4f}, unshot {:.2f}%\n", scene.source,
             solver.patches().size(), solver.history().size(), solver.convergence(),
             100.0 * solver.ledger().unshotFraction());
  warnAfterSolve(solver.ledger(), solver.options(), static_cast<long long>(solver.history().size()),
                 solver.effectsPlan().closed, args.iterations > 0);
  return solvedFrom(solver.elements(), solver.displayElementRadiosity());
}

std::optional<Solved> readBakeToRender(const RenderArgs& args) {
  std::optional<Bake> bake = readCommandBake(args.flags.scene, args.flags.up, args.flags.given());
  if (!bake) return std::nullopt;  // a scene to solve, not a bake
  if (args.iterations > 0)
    throw OptionError(fmt::format("{} is a bake, already solved: --iterations applies to scenes", args.flags.scene));
  fmt::print("read bake {}: {} vertices, {} triangles\n", args.flags.scene, bake->mesh.positions.size(),
             bake->mesh.indices.size() / 3);
  const RenderView view = chooseView(args, sceneFrame(bakeScene(*bake, args.flags.scene)));
  return Solved{std::move(bake->mesh), std::move(bake->vertexB), view};
}

void run(const RenderArgs& args) {
  const glm::ivec2 size = pictureSize(args.size, usableMemoryBytes());
  if (!(args.fovDeg >= kMinFovDeg && args.fovDeg <= kMaxFovDeg))
    throw OptionError(fmt::format("--fov must be from {} to {} degrees (narrower, the picture's single-precision "
                                  "projection has no pixels left; wider, the walls beside the eye fall before its "
                                  "near plane and the picture's sides go black), got {}",
                                  kMinFovDeg, kMaxFovDeg, args.fovDeg));
  checkOutputPath("--out", args.outPath, ".png", "the picture is PNG");
  checkOutputsDistinct(args.flags.scene, {{"--out", args.outPath}});  // a link named .png may lead to the scene
  std::optional<Solved> solved = readBakeToRender(args);
  if (!solved) solved = solveScene(args);
  const RenderView& view = solved->view;

  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  OffscreenRenderer renderer(solved->mesh, size);
  OffscreenShading shading;
  shading.exposure = args.exposureEv ? std::exp2(*args.exposureEv) : autoExposure(solved->mesh, solved->vertexB);
  fmt::print("exposure {:+.2f} EV ({}; --exposure sets it)\n", std::log2(*shading.exposure),
             args.exposureEv ? "given" : "automatic");
  Image image = renderer.render(solved->vertexB, view, shading);
  const double firstMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  const auto warm = Clock::now();
  for (int frame = 1; frame < args.frames; ++frame) image = renderer.render(solved->vertexB, view, shading);
  // Timed and said before the PNG is encoded, which takes seconds for the largest pictures.
  if (args.frames > 1)
    fmt::print("rendered {}x{}: first frame {:.1f} ms (context, upload, shader compile), then {:.2f} ms per frame "
               "(draw and read back) over {} frames\n",
               size.x, size.y, firstMs,
               std::chrono::duration<double, std::milli>(Clock::now() - warm).count() / (args.frames - 1),
               args.frames - 1);
  else
    fmt::print("rendered {}x{} in {:.1f} ms (context, upload, shader compile and one frame)\n", size.x, size.y,
               firstMs);
  if (backgroundPixels(image) == static_cast<long long>(size.x) * size.y)
    fmt::print(stderr, "radmesh: warning: the picture shows nothing of the model: is the camera outside it looking "
                       "away, or too far off (--camera, --look)?\n");
  std::fflush(stdout);
  writePng(image, args.outPath);
  fmt::print("wrote {}\n", args.outPath);
}

}  // namespace

void addRenderCommand(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Solve a scene (or read a bake) and render a view offscreen to PNG");
  addSolveFlags(cmd, args->flags);
  addViewFlags(cmd, args->start, args->exposureEv);
  cmd->add_option("--fov", args->fovDeg, "Vertical field of view, degrees")->capture_default_str();
  cmd->add_option("--size", args->size, "Image size WxH in pixels")->capture_default_str();
  CLI::Option* iterations =
      cmd->add_option("--iterations", args->iterations,
                      "Solve this many iterations and no convergence stop: --until 1 --until-unshot 0 "
                      "--max-iterations N (sooner only once no power is left; with --cells auto, at the end of the "
                      "round that reaches N)")
          ->check(kPositive);
  for (const char* stop : {"--until", "--until-unshot", "--max-iterations"}) cmd->get_option(stop)->excludes(iterations);
  cmd->add_option("--frames", args->frames, "Draw this many frames and report ms per frame (timing)")
      ->check(CLI::Range(1, 100000));
  cmd->add_flag("--quiet", args->quiet, "No progress lines");
  cmd->add_option("--out", args->outPath, "PNG file to write")->required();
  cmd->callback([args] { run(*args); });
}

#else

void addRenderCommand(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("render", "Render offscreen (not built: configure with RADMESH_BUILD_VIEWER=ON)");
  cmd->allow_extras();
  cmd->callback([] {
    throw OptionError("this radmesh was built without the viewer: reconfigure with -DRADMESH_BUILD_VIEWER=ON");
  });
}

#endif

}  // namespace radmesh::cli
