#include "viewer/viewer_app.h"

#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "solver/bake/bake_reader.h"
#include "solver/io/scene_loader.h"
#include "solver/meshing/meshing.h"
#include "viewer/camera.h"
#include "viewer/cell_visibility.h"
#include "viewer/exposure.h"
#include "viewer/frame_report.h"
#include "viewer/imgui_layer.h"
#include "viewer/panel.h"
#include "viewer/renderer.h"
#include "viewer/solver_thread.h"
#include "viewer/viewed_file.h"
#include "viewer/walk_input.h"
#include "viewer/window_context.h"

namespace radmesh {

namespace {

using Clock = std::chrono::steady_clock;

// Hands the renderer what changed since the last snapshot it drew.
class SnapshotFeed {
 public:
  void show(const std::shared_ptr<const SolverSnapshot>& snapshot, Renderer& renderer, ViewSettings& view) {
    if (snapshot == shown_) return;
    if (!shown_ || snapshot->generation != shown_->generation || snapshot->mesh != shown_->mesh) {
      renderer.setMesh(snapshot->mesh ? *snapshot->mesh : DisplayMesh{});
      if (snapshot->mesh && snapshot->cells)
        renderer.setCells(*snapshot->cells->cellOfReceiver,
                          static_cast<int>(snapshot->cells->partition->cells.size()));
    }
    if (snapshot->mesh) {
      renderer.setVertexRadiosity(snapshot->vertexB);
      renderer.setHighlightedPatches(snapshot->lastShooterElements);
      if (view.autoExposure) view.exposureStops = std::log2(snapshot->exposure);
    }
    shown_ = snapshot;
  }
  const SolverSnapshot& shown() const { return *shown_; }

 private:
  std::shared_ptr<const SolverSnapshot> shown_;
};

// Frame times, apart while the solver thread iterates and while it is idle: the cost of drawing
// alone, and of drawing beside a busy solver.
class FrameStats {
 public:
  void add(double seconds, bool solving) {
    Phase& p = solving ? solving_ : idle_;
    ++p.frames;
    p.seconds += seconds;
  }
  void print(glm::ivec2 size, const std::string& state) const {
    std::printf("radmesh-view: %dx%d; %s\n", size.x, size.y, state.c_str());
    print("while solving", solving_);
    print("solver idle", idle_);
  }

 private:
  struct Phase {
    long frames = 0;
    double seconds = 0.0;
  };
  static void print(const char* name, const Phase& p) {
    if (p.frames == 0) return;
    std::printf("radmesh-view: %s: %ld frames in %.2f s, %.1f fps (%.2f ms per frame)\n", name, p.frames, p.seconds,
                p.frames / std::max(p.seconds, 1e-9), 1e3 * p.seconds / p.frames);
  }
  Phase solving_, idle_;
};

// What the window shows: a solve converging on its own thread, or a bake.
class Shown {
 public:
  virtual ~Shown() = default;
  // Hands the renderer what changed, and the solve where the camera is.
  virtual void feed(Renderer& renderer, ViewSettings& view, WalkCamera& camera) = 0;
  virtual bool meshShown() const = 0;
  // Before drawing: what the renderer may leave out, seen from `view`.
  virtual void cull(Renderer&, const RenderView&, double /*aspect*/, const ViewSettings&) {}
  virtual void drawPanel(Panel& panel, WalkCamera& camera, ViewSettings& view) = 0;
  virtual void saveCheckpoint(const Panel&) {}
  virtual bool solving() const = 0;  // the frame statistics keep these frames apart
  // Smoke test: ready for the screenshot, and why it failed (empty: it did not).
  virtual bool ready() const = 0;
  virtual std::string failure() const { return {}; }
  virtual int failureExitCode() const { return 1; }  // 2 for the user's input, as radmesh's
  virtual std::string state() const = 0;  // for the frame statistics
};

class ShownSolve : public Shown {
 public:
  ShownSolve(Scene scene, const SolveSetup& setup, const ViewerArgs& args, const Vec3& eye)
      : smokeTest_(args.steps > 0), reportsAtExit_(args.steps > 0 || args.frames > 0),
        solver_(std::move(scene), setup, !smokeTest_, args.resume, args.steps, eye) {}
  void feed(Renderer& renderer, ViewSettings& view, WalkCamera& camera) override {
    solver_.setEye(camera.view().eye);
    feed_.show(solver_.latest(), renderer, view);
    // Said in the terminal too, once each: a --cell too fine for the scene is found on the solver
    // thread, after the window opened (--steps and --frames say it as they exit).
    if (const std::string& error = feed_.shown().error; !reportsAtExit_ && !error.empty() && error != printedError_) {
      std::fprintf(stderr, "radmesh-view: the solve failed: %s\n", error.c_str());
      printedError_ = error;
    }
    // A camera outside every room (the scene's corner is outside a building) goes into the room
    // solved first, once a solve; not one looking into an open-sided model from outside (a Cornell
    // box's start view went inside it, into the void behind its open side), nor one put where it
    // is by --camera or --look.
    const SolverSnapshot& s = feed_.shown();
    if (s.cells && s.cells->focus >= 0 && s.generation != placedGeneration_ && !camera.looksInFromOutside() &&
        !camera.startGiven()) {
      placedGeneration_ = s.generation;
      const std::vector<Cell>& cells = s.cells->partition->cells;
      if (!s.cells->eyeInFocus && s.cells->focus < static_cast<int>(cells.size()))
        camera.standIn(cells[s.cells->focus].boundsMin, cells[s.cells->focus].boundsMax, {-1.0, -1.0},
                       WalkCamera::kCellReach);
    }
  }
  bool meshShown() const override { return feed_.shown().mesh != nullptr; }
  void cull(Renderer& renderer, const RenderView& view, double aspect, const ViewSettings& settings) override {
    const SolverSnapshot& s = feed_.shown();
    if (s.mesh && s.cells)
      renderer.setVisibleCells(settings.cullCells ? visibleCells(*s.cells->partition, viewProjectionMatrix(view, aspect), view.eye)
                                                  : std::vector<bool>{});
  }
  void drawPanel(Panel& panel, WalkCamera& camera, ViewSettings& view) override {
    panel.draw(feed_.shown(), solver_, camera, view);
  }
  void saveCheckpoint(const Panel& panel) override { panel.saveCheckpoint(solver_); }
  bool solving() const override { return smokeTest_ ? !ready() : feed_.shown().playing && !feed_.shown().done; }
  // The steps are counted from where the solve starts: a resumed checkpoint's iteration, not 0.
  bool ready() const override {
    const SolverSnapshot& s = feed_.shown();
    return (s.mesh && s.stepsLeft == 0) || s.done || s.exhausted || !s.error.empty();
  }
  std::string failure() const override {
    return feed_.shown().error.empty() ? "" : "the solve failed: " + feed_.shown().error;
  }
  int failureExitCode() const override { return feed_.shown().errorIsInput ? 2 : 1; }
  std::string state() const override {
    const SolverSnapshot& s = feed_.shown();
    char line[160];
    if (s.cells)
      std::snprintf(line, sizeof line, "cells solve at round %d, %d iterations, unshot %.2f%%", s.cells->rounds,
                    s.iteration(), 100.0 * s.ledger.unshotFraction());
    else
      std::snprintf(line, sizeof line, "solver at iteration %d, C = %.4f", s.iteration(), s.convergence());
    return line;
  }

 private:
  std::uint64_t placedGeneration_ = 0;  // the solve whose cells placed the camera
  std::string printedError_;            // the last failure said in the terminal
  bool smokeTest_;
  bool reportsAtExit_;
  SolverThread solver_;
  SnapshotFeed feed_;
};

class ShownBake : public Shown {
 public:
  ShownBake(const std::string& path, Bake bake) : bake_(std::move(bake)), exposure_(autoExposure(bake_.mesh, bake_.vertexB)) {
    description_ = "bake " + path + " (by " + (bake_.fromRadmesh ? "radmesh" : "another tool") + "), " +
                   std::to_string(bake_.mesh.indices.size() / 3) + " triangles, up " +
                   upAxisName(bake_.upAxis);
  }
  bool meshShown() const override { return true; }
  void feed(Renderer& renderer, ViewSettings& view, WalkCamera&) override {
    if (!fed_) {
      renderer.setMesh(bake_.mesh);
      renderer.setVertexRadiosity(bake_.vertexB);
      fed_ = true;
    }
    if (view.autoExposure) view.exposureStops = std::log2(exposure_);
  }
  void drawPanel(Panel& panel, WalkCamera& camera, ViewSettings& view) override {
    panel.drawBake(description_, camera, view);
  }
  bool solving() const override { return false; }
  bool ready() const override { return true; }
  std::string state() const override { return "a bake, nothing to solve"; }

 private:
  Bake bake_;
  double exposure_;  // the bake's auto exposure: it never changes
  std::string description_;
  bool fed_ = false;
};

}  // namespace

SolveSetup viewerSetup() {
  SolveSetup setup;
  applyPreset(Preset::Paper, setup.options);
  setup.options.backend = Backend::Mesh;
  setup.options.until = 1.0;
  setup.options.untilUnshot = 0.01;
  return setup;
}

namespace {

void printMessages(const ViewedFile& file) {
  for (const std::string& warning : file.warnings) std::fprintf(stderr, "radmesh-view: warning: %s\n", warning.c_str());
  for (const std::string& note : file.notes) std::printf("radmesh-view: %s\n", note.c_str());
}

// What a file shows, walked from `start`. A solve's --resume checkpoint is read and checked here,
// and refused as radmesh solve refuses it: the launch's is made before the window for that.
struct Opened {
  Opened(ViewedFile file, const WalkCamera& start, const ViewerArgs& args) : camera(start), setup(file.setup) {
    if (file.bake)
      shown = std::make_unique<ShownBake>(file.path, std::move(*file.bake));
    else
      shown = std::make_unique<ShownSolve>(std::move(file.scene), file.setup, args, camera.view().eye);
  }
  WalkCamera camera;
  SolveSetup setup;
  std::unique_ptr<Shown> shown;
};

// One file in the window: what it shows, the walk through it, its panel and the renderer of its
// mesh (GL objects: made with the window's context current). Opening another file makes them anew.
struct Viewing {
  Viewing(Opened opened, const ViewerArgs& args)
      : camera(opened.camera), shown(std::move(opened.shown)), panel(opened.setup, args.firstTab, args.checkpoint) {}
  WalkCamera camera;
  std::unique_ptr<Shown> shown;
  Panel panel;
  Renderer renderer;
};

// A file dropped on the window, kept until the frame loop takes it.
void keepDroppedPath(GLFWwindow* window, int count, const char** paths) {
  if (count > 0) *static_cast<std::optional<std::string>*>(glfwGetWindowUserPointer(window)) = paths[count - 1];
}

}  // namespace

int runViewer(const ViewerArgs& args) {
  ViewedFile file = readViewedFile(args.scene, args);
  printMessages(file);
  if (file.bake)
    for (const std::string& flag : args.solveFlags)
      std::fprintf(stderr, "radmesh-view: warning: %s does not apply: %s is a bake, already solved (it applies to scenes)\n",
                   flag.c_str(), args.scene.c_str());
  const std::string title = "radmesh-view: " + file.scene.source;
  // Refused, if it must be, before the window opens, as radmesh render refuses it before its solve.
  WalkCamera start(sceneFrame(file.scene));
  start.startFrom(args.start);
  // A --resume checkpoint is checked before the window, as radmesh solve refuses it; otherwise the
  // window comes first, so a missing display is said at once, not after the solver thread (which
  // cannot stop while it meshes) has meshed the scene.
  std::optional<Opened> first;
  if (!args.resume.empty()) first.emplace(std::move(file), start, args);
  WindowContext window(title, args.windowSize);
  if (!first) first.emplace(std::move(file), start, args);
  ImGuiLayer imgui(window.window());
  std::optional<std::string> dropped;
  glfwSetWindowUserPointer(window.window(), &dropped);
  glfwSetDropCallback(window.window(), keepDroppedPath);
  const bool smokeTest = args.steps > 0;
  auto viewing = std::make_unique<Viewing>(std::move(*first), args);
  // Files opened later start from scratch and run until told: the launch's checkpoint and smoke test
  // were its own, as were its camera and exposure.
  ViewerArgs later = args;
  later.resume.clear();
  later.steps = 0;
  ViewSettings view;
  if (args.exposureEv) view.exposureStops = *args.exposureEv, view.autoExposure = false;
  WalkInputReader input;

  auto lastFrame = Clock::now();
  FrameStats stats;
  FrameReport report;
  long frames = 0;
  int framesSinceReady = 0;
  int exitCode = 0;
  bool saveKeyWasDown = false;  // F5 saves once per press
  double feedSeconds = 0.0;     // the last frame's, for the report
  long framesWithMesh = 0;
  // Another file in the window: read before anything is let go, so a file that cannot be read
  // leaves the scene as it was, with the reason in the panel.
  auto open = [&](const std::string& path) {
    try {
      ViewedFile opened = readViewedFile(path, later);
      const WalkCamera camera(sceneFrame(opened.scene));
      printMessages(opened);
      glfwSetWindowTitle(window.window(), ("radmesh-view: " + opened.scene.source).c_str());
      const std::string message = fmt::format("opened {}{}", opened.scene.source,
                                              opened.warnings.empty() ? "" : fmt::format(" ({} warnings: see the terminal)", opened.warnings.size()));
      viewing.reset();  // its solver thread stops before the next one starts
      viewing = std::make_unique<Viewing>(Opened(std::move(opened), camera, later), later);
      viewing->panel.setOpenMessage(path, message, false);
      view.autoExposure = true;
    } catch (const std::exception& e) {
      if (!viewing) throw;  // the file was read, but the window could not be set up for it
      const std::string failure = openFailure(path, e.what());
      std::fprintf(stderr, "radmesh-view: %s\n", failure.c_str());
      viewing->panel.setOpenMessage(path, failure, true);
    }
  };
  while (!window.shouldClose()) {
    glfwPollEvents();
    if (glfwGetKey(window.window(), GLFW_KEY_ESCAPE) == GLFW_PRESS && !imgui.wantsKeyboard()) window.requestClose();
    const bool saveKeyDown = glfwGetKey(window.window(), GLFW_KEY_F5) == GLFW_PRESS;
    if (saveKeyDown && !saveKeyWasDown && !imgui.wantsKeyboard()) viewing->shown->saveCheckpoint(viewing->panel);
    saveKeyWasDown = saveKeyDown;
    const auto now = Clock::now();
    const double dt = std::chrono::duration<double>(now - lastFrame).count();
    lastFrame = now;
    // dt is the previous frame's time; it counts where that frame's snapshot stood.
    if (frames > 0) stats.add(dt, viewing->shown->solving());
    // The report starts a frame after the mesh's: taking in a new mesh is not drawing.
    if (args.frames > 0 && framesWithMesh >= 2) report.add(dt, feedSeconds);

    // Before the feed: a new file's Shown has had no snapshot until it is fed once.
    if (std::optional<std::string> path = dropped ? std::exchange(dropped, std::nullopt) : viewing->panel.takeOpenRequest())
      open(*path);
    const auto feedStart = Clock::now();
    viewing->shown->feed(viewing->renderer, view, viewing->camera);
    feedSeconds = std::chrono::duration<double>(Clock::now() - feedStart).count();
    if (viewing->shown->meshShown()) ++framesWithMesh;
    viewing->camera.update(input.read(window.window(), !imgui.wantsKeyboard(), !imgui.wantsMouse()), dt);
    const glm::ivec2 size = window.framebufferSize();
    const glm::ivec2 sceneSize{std::max(1, size.x - int(Panel::kWidthPx)), size.y};
    viewing->shown->cull(viewing->renderer, viewing->camera.view(), double(sceneSize.x) / double(sceneSize.y), view);
    viewing->renderer.draw(viewing->camera.view(), sceneSize, Shading{std::exp2(view.exposureStops), view.highlightShooters});
    imgui.beginFrame();
    viewing->shown->drawPanel(viewing->panel, viewing->camera, view);
    imgui.endFrame();
    ++frames;

    // The panel lays itself out over a couple of frames: wait for them before the screenshot.
    const bool smokeTestDone = smokeTest && viewing->shown->ready() && ++framesSinceReady >= 3 && frames >= args.minFrames;
    // A solve that fails before its mesh shows would leave the frame report waiting for ever.
    const bool reportDone =
        args.frames > 0 && (report.frames() >= args.frames || !viewing->shown->failure().empty());
    if (smokeTestDone || reportDone) {
      if (!viewing->shown->failure().empty()) {
        std::fprintf(stderr, "radmesh-view: %s\n", viewing->shown->failure().c_str());
        exitCode = viewing->shown->failureExitCode();
      } else if (!args.screenshot.empty()) {
        writePng(captureFramebuffer(size), args.screenshot);
        std::printf("wrote %s\n", args.screenshot.c_str());
      }
      window.requestClose();
    }
    window.swapBuffers();
  }

  if (!args.quiet) stats.print(window.framebufferSize(), viewing->shown->state());
  if (const std::string summary = report.summary(); !summary.empty()) std::printf("radmesh-view: %s\n", summary.c_str());
  return exitCode;
}

}  // namespace radmesh
