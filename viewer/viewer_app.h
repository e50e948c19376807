#pragma once
// `radmesh-view`: the walkthrough window while the solver converges on its own thread.
#include <glm/vec2.hpp>

#include <optional>
#include <string>
#include <vector>

#include "solver/io/daylight.h"
#include "solver/scene/up_axis.h"
#include "viewer/camera.h"
#include "viewer/panel.h"
#include "viewer/solver_snapshot.h"

namespace radmesh {

// The walkthrough's default solve: the emulated MP-1 with the paper's single plane at 128², there to
// watch the machine; but it stops when 1 % of the emitted power is left unshot, not at C = 0.95,
// which leaves a third of it (docs/accuracy.md).
SolveSetup viewerSetup();

struct ViewerArgs {
  std::string scene = "office";  // or a bake (solver/bake/bake_reader.h), walked with no solve
  UpChoice up = UpChoice::Format;
  double metresPerUnit = 0.0;  // --units; 0: not given
  bool strict = false;         // --strict: a scene that needed any repair is refused, as radmesh solve's
  SolveSetup setup = viewerSetup();
  bool cellGiven = false;  // --cell; else setup.cellM is chosen from the scene's size
  // --preset elements without --min-element: each scene's patches are elementsPresetCell of its
  // chosen cell (unless --cell), its elements a quarter of that (solver/scene/solve_options.h).
  bool elementsPreset = false;
  Daylight daylight;       // --sky, --sky-model
  glm::ivec2 windowSize{1280, 720};
  // The launch's file is first seen from here (--camera, --look) at this exposure (--exposure;
  // none: automatic); a file opened later starts at its own walkthrough start, exposed automatically.
  ViewStart start;
  std::optional<double> exposureEv;
  bool quiet = false;  // --quiet: no frame statistics on exit
  PanelTab firstTab = PanelTab::Progress;
  std::string resume;                       // a checkpoint to go on from (empty: from scratch)
  std::string checkpoint = "radmesh-view.ckpt";  // where the panel's Save checkpoint writes
  // Smoke-test mode when steps > 0: solve this many iterations (paused after), save a screenshot
  // of the whole window with its panel, and exit. Frame statistics are printed on exit.
  int steps = 0;
  long minFrames = 0;  // and draw at least this many frames first (for timing)
  std::string screenshot;
  // Frame-time report when frames > 0: solve (playing) while drawing this many frames from the
  // first that shows the mesh, print their frame rates (lowest, median), save --screenshot, exit.
  long frames = 0;
  // The solve's flags given (--cell, --resume...): each is warned of as not applying to a bake.
  std::vector<std::string> solveFlags;
};

// Returns the process exit code; throws SceneError, OptionError or std::runtime_error (no
// display, no OpenGL 3.3) with a message for the user.
int runViewer(const ViewerArgs& args);

}  // namespace radmesh
