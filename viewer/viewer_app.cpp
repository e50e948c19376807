#include "viewer/viewer_app.h"

#include <GLFW/glfw3.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "solver/io/scene_loader.h"
#include "solver/meshing/meshing.h"
#include "viewer/camera.h"
#include "viewer/exposure.h"
#include "viewer/imgui_layer.h"
#include "viewer/panel.h"
#include "viewer/renderer.h"
#include "viewer/solver_thread.h"
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
    if (!shown_ || snapshot->generation != shown_->generation || snapshot->mesh != shown_->mesh)
      renderer.setMesh(snapshot->mesh ? *snapshot->mesh : DisplayMesh{});
    if (snapshot->mesh) {
      renderer.setVertexRadiosity(snapshot->vertexB);
      renderer.setHighlightedPatches(snapshot->lastShooters);
      if (view.autoExposure) view.exposureStops = std::log2(autoExposure(*snapshot->mesh, snapshot->vertexB));
    }
    shown_ = snapshot;
  }
  const SolverSnapshot& shown() const { return *shown_; }

 private:
  std::shared_ptr<const SolverSnapshot> shown_;
};

bool smokeTestReady(const ViewerArgs& args, const SolverSnapshot& snapshot) {
  return snapshot.iteration() >= args.steps || snapshot.done || !snapshot.error.empty();
}

// Frame times, apart while the solver thread iterates and while it is idle: the cost of drawing
// alone, and of drawing beside a busy solver.
class FrameStats {
 public:
  void add(double seconds, bool solving) {
    Phase& p = solving ? solving_ : idle_;
    ++p.frames;
    p.seconds += seconds;
  }
  void print(glm::ivec2 size, const SolverSnapshot& snapshot) const {
    std::printf("radmesh-view: %dx%d; solver at iteration %d, C = %.4f\n", size.x, size.y, snapshot.iteration(),
                snapshot.convergence());
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

}  // namespace

SolveSetup viewerSetup() {
  SolveSetup setup;
  applyPreset(Preset::Paper, setup.options);
  setup.options.backend = Backend::Mesh;
  setup.options.until = 1.0;
  setup.options.untilUnshot = 0.01;
  return setup;
}

int runViewer(const ViewerArgs& args) {
  std::vector<std::string> warnings, notes;
  Scene scene = loadScene(args.scene, &warnings, args.daylight, &notes);
  for (const std::string& warning : warnings) std::fprintf(stderr, "radmesh-view: warning: %s\n", warning.c_str());
  for (const std::string& note : notes) std::printf("radmesh-view: %s\n", note.c_str());
  SolveSetup setup = args.setup;
  if (!args.cellGiven) {
    const CellChoice cell = chooseCell(scene);
    setup.cellM = cell.cellM;
    std::printf("radmesh-view: %s\n", cell.why.c_str());
  }
  const std::string title = "radmesh-view: " + scene.source;
  WalkCamera camera(sceneFrame(scene));

  WindowContext window(title, args.windowSize);
  ImGuiLayer imgui(window.window());
  Renderer renderer;
  const bool smokeTest = args.steps > 0;
  SolverThread solver(std::move(scene), setup, !smokeTest, args.resume);
  if (smokeTest) solver.step(args.steps);
  Panel panel(setup, args.firstTab, args.checkpoint);
  ViewSettings view;
  SnapshotFeed feed;
  WalkInputReader input;

  auto lastFrame = Clock::now();
  FrameStats stats;
  long frames = 0;
  int framesSinceReady = 0;
  int exitCode = 0;
  bool saveKeyWasDown = false;  // F5 saves once per press
  while (!window.shouldClose()) {
    glfwPollEvents();
    if (glfwGetKey(window.window(), GLFW_KEY_ESCAPE) == GLFW_PRESS && !imgui.wantsKeyboard()) window.requestClose();
    const bool saveKeyDown = glfwGetKey(window.window(), GLFW_KEY_F5) == GLFW_PRESS;
    if (saveKeyDown && !saveKeyWasDown && !imgui.wantsKeyboard()) panel.saveCheckpoint(solver);
    saveKeyWasDown = saveKeyDown;
    const auto now = Clock::now();
    const double dt = std::chrono::duration<double>(now - lastFrame).count();
    lastFrame = now;
    // dt is the previous frame's time; it counts where that frame's snapshot stood.
    if (frames > 0) stats.add(dt, smokeTest ? !smokeTestReady(args, feed.shown()) : feed.shown().playing && !feed.shown().done);

    feed.show(solver.latest(), renderer, view);
    camera.update(input.read(window.window(), !imgui.wantsKeyboard(), !imgui.wantsMouse()), dt);
    const glm::ivec2 size = window.framebufferSize();
    const glm::ivec2 sceneSize{std::max(1, size.x - int(Panel::kWidthPx)), size.y};
    renderer.draw(camera.view(), sceneSize, Shading{std::exp2(view.exposureStops), view.highlightShooters});
    imgui.beginFrame();
    panel.draw(feed.shown(), solver, camera, view);
    imgui.endFrame();
    ++frames;

    // The panel lays itself out over a couple of frames: wait for them before the screenshot.
    if (smokeTest && smokeTestReady(args, feed.shown()) && ++framesSinceReady >= 3 && frames >= args.minFrames) {
      if (!feed.shown().error.empty()) {
        std::fprintf(stderr, "radmesh-view: the solve failed: %s\n", feed.shown().error.c_str());
        exitCode = 1;
      } else if (!args.screenshot.empty()) {
        writePng(captureFramebuffer(size), args.screenshot);
        std::printf("wrote %s\n", args.screenshot.c_str());
      }
      window.requestClose();
    }
    window.swapBuffers();
  }

  stats.print(window.framebufferSize(), feed.shown());
  return exitCode;
}

}  // namespace radmesh
