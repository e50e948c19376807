#pragma once
// The ImGui panel: the solve's state and commands on top, then tabs for its progress
// (convergence curves, timing, energy ledger), the last shot's item buffer, the solve parameters,
// the scene's figures and the view. Commands go to the solver thread; everything shown comes from
// its latest snapshot.
#include <array>
#include <memory>
#include <optional>
#include <string>

#include "viewer/camera.h"
#include "viewer/exposure.h"
#include "viewer/gl_texture.h"
#include "viewer/solver_snapshot.h"
#include "viewer/solver_thread.h"

namespace radmesh {

struct ViewSettings {
  double exposureStops = 0.0;  // log2 of the linear exposure factor
  bool autoExposure = true;    // follow autoExposure() as the light streams in
  bool highlightShooters = true;
  // With cells: draw only the rooms the eye may see through portals (viewer/cell_visibility.h);
  // a room seen across the outside, through two windows, is then left out.
  bool cullCells = true;
};

enum class PanelTab { Progress, ItemBuffer, Parameters, Scene, View };
// "progress", "item-buffer", "parameters", "scene", "view"; throws OptionError otherwise.
PanelTab parsePanelTab(const std::string& name);

class Panel {
 public:
  static constexpr float kWidthPx = 380.0f;  // docked at the window's right edge

  // Needs the window's GL context current (the item buffer is shown from a texture).
  // checkpointPath: where "Save checkpoint" (or F5) saves the solve, editable in the panel.
  Panel(const SolveSetup& setup, PanelTab firstTab, const std::string& checkpointPath);

  void draw(const SolverSnapshot& snapshot, SolverThread& solver, WalkCamera& camera, ViewSettings& view);
  void saveCheckpoint(SolverThread& solver) const { solver.saveCheckpoint(checkpointPath_.data()); }
  // A bake's panel: what it is, and the view settings; no solver controls (it is solved already).
  void drawBake(const std::string& description, WalkCamera& camera, ViewSettings& view);
  // The Open field atop either panel: the path the user asked to open, once.
  std::optional<std::string> takeOpenRequest();
  // Shown under the Open field: what the last open did (failed: in red, and the scene stays).
  void setOpenMessage(const std::string& path, const std::string& message, bool failed);

 private:
  void begin();  // the panel's window, docked at the right, with the Open field on top
  void drawOpen();
  void drawStateAndCommands(const SolverSnapshot& snapshot, SolverThread& solver);
  void drawProgress(const SolverSnapshot& snapshot);
  void drawMachineCost(const SolverSnapshot& snapshot);
  void drawItemBuffer(const SolverSnapshot& snapshot);
  void drawShotFigures(const SolverSnapshot& snapshot);
  void drawParameters(SolverThread& solver);
  void drawScene(const SolverSnapshot& snapshot);
  void drawView(WalkCamera& camera, ViewSettings& view, bool solving);
  bool beginTab(const char* label, PanelTab tab);

  SolveSetup edited_;
  PanelTab firstTab_;
  bool firstFrame_ = true;
  std::string parameterError_;
  int stepCount_ = 10;
  std::array<char, 1024> checkpointPath_{};
  std::array<char, 1024> openPath_{};
  std::optional<std::string> openRequest_;
  std::string openMessage_;
  bool openFailed_ = false;
  bool itemBufferWanted_ = false;
  StopsSpan exposureSpan_;
  GlTexture itemBufferTexture_;
  std::shared_ptr<const ItemBuffer> uploadedItemBuffer_;
};

}  // namespace radmesh
