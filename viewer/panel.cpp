#include "viewer/panel.h"

#include <imgui.h>

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "solver/scene/scene_error.h"
#include "viewer/panel_widgets.h"
#include "viewer/solve_warnings.h"

namespace radmesh {

namespace {

// A cell counts as settled at this unshot fraction (the target for the camera's room).
constexpr double kCellSettledUnshot = 0.05;

void row(const char* name, const char* format, double value) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(name);
  ImGui::TableNextColumn();
  ImGui::Text(format, value);
}

// A cells solve's state: the camera's cell, and every cell by portal distance (folded).
void drawCellsState(const CellsProgress& cells) {
  const int settled = static_cast<int>(std::count_if(cells.cells.begin(), cells.cells.end(), [](const auto& c) {
    return c.unshotFraction <= kCellSettledUnshot;
  }));
  if (cells.focus >= 0 && cells.focus < static_cast<int>(cells.cells.size())) {
    const CellsProgress::Row& focus = cells.cells[cells.focus];
    ImGui::Text("%s '%s': unshot %.2f%%, %d iterations", cells.eyeInFocus ? "camera in" : "camera in no room; first",
                focus.name.c_str(), 100.0 * focus.unshotFraction, focus.iterations);
  } else {
    ImGui::TextUnformatted("no camera cell yet: every cell shoots alike");
  }
  ImGui::Text("%zu cells, %d at %.0f%% unshot or less", cells.cells.size(), settled, 100.0 * kCellSettledUnshot);
  if (!ImGui::CollapsingHeader("cells by portal distance")) return;
  std::vector<int> order(cells.cells.size());
  for (size_t c = 0; c < order.size(); ++c) order[c] = static_cast<int>(c);
  auto rank = [&](int c) { return cells.cells[c].portalDistance < 0 ? 1 << 30 : cells.cells[c].portalDistance; };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return rank(a) < rank(b); });
  if (ImGui::BeginTable("cells", 4, ImGuiTableFlags_ScrollY, ImVec2(0.0f, 160.0f))) {
    ImGui::TableSetupColumn("cell");
    ImGui::TableSetupColumn("portals");
    ImGui::TableSetupColumn("unshot");
    ImGui::TableSetupColumn("iterations");
    ImGui::TableHeadersRow();
    ImGuiListClipper clipper;  // only the rows in sight: a building has hundreds
    clipper.Begin(static_cast<int>(order.size()));
    while (clipper.Step())
      for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
        const CellsProgress::Row& c = cells.cells[order[i]];
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(c.name.c_str());
        ImGui::TableNextColumn();
        ImGui::Text("%d", c.portalDistance);
        ImGui::TableNextColumn();
        ImGui::Text("%.2f%%", 100.0 * c.unshotFraction);
        ImGui::TableNextColumn();
        ImGui::Text("%d", c.iterations);
      }
    ImGui::EndTable();
  }
}

}  // namespace

PanelTab parsePanelTab(const std::string& name) {
  if (name == "progress") return PanelTab::Progress;
  if (name == "item-buffer") return PanelTab::ItemBuffer;
  if (name == "parameters") return PanelTab::Parameters;
  if (name == "scene") return PanelTab::Scene;
  if (name == "view") return PanelTab::View;
  throw OptionError("--panel '" + name + "' is not a tab: use progress, item-buffer, parameters, scene or view");
}

Panel::Panel(const SolveSetup& setup, PanelTab firstTab, const std::string& checkpointPath)
    : edited_(setup), firstTab_(firstTab) {
  std::strncpy(checkpointPath_.data(), checkpointPath.c_str(), checkpointPath_.size() - 1);
}

void Panel::begin() {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + viewport->WorkSize.x - kWidthPx, viewport->WorkPos.y));
  ImGui::SetNextWindowSize(ImVec2(kWidthPx, viewport->WorkSize.y));
  ImGui::Begin("radmesh", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  drawOpen();
}

void Panel::drawOpen() {
  const bool entered = ImGui::Button("Open");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-FLT_MIN);
  const bool typed = ImGui::InputTextWithHint("##open", "a scene (name or file) or a bake; or drop a file here",
                                              openPath_.data(), openPath_.size(), ImGuiInputTextFlags_EnterReturnsTrue);
  if ((entered || typed) && openPath_[0] != '\0') openRequest_ = std::string(openPath_.data());
  if (openMessage_.empty()) return;
  if (openFailed_)
    failureText(openMessage_.c_str());
  else
    ImGui::TextWrapped("%s", openMessage_.c_str());
}

std::optional<std::string> Panel::takeOpenRequest() { return std::exchange(openRequest_, std::nullopt); }

void Panel::setOpenMessage(const std::string& path, const std::string& message, bool failed) {
  std::strncpy(openPath_.data(), path.c_str(), openPath_.size() - 1);
  openMessage_ = message;
  openFailed_ = failed;
}

void Panel::drawBake(const std::string& description, WalkCamera& camera, ViewSettings& view) {
  begin();
  ImGui::TextWrapped("%s", description.c_str());
  note("a bake: its light is already solved, so there is nothing to solve here");
  ImGui::Separator();
  drawView(camera, view, /*solving=*/false);
  ImGui::End();
}

void Panel::draw(const SolverSnapshot& snapshot, SolverThread& solver, WalkCamera& camera, ViewSettings& view) {
  begin();
  drawStateAndCommands(snapshot, solver);
  bool itemBufferShown = false;
  if (ImGui::BeginTabBar("tabs")) {
    if (beginTab("Progress", PanelTab::Progress)) {
      drawProgress(snapshot);
      ImGui::EndTabItem();
    }
    if (beginTab("Item buffer", PanelTab::ItemBuffer)) {
      itemBufferShown = true;
      drawItemBuffer(snapshot);
      ImGui::EndTabItem();
    }
    if (beginTab("Parameters", PanelTab::Parameters)) {
      drawParameters(solver);
      ImGui::EndTabItem();
    }
    if (beginTab("Scene", PanelTab::Scene)) {
      drawScene(snapshot);
      ImGui::EndTabItem();
    }
    if (beginTab("View", PanelTab::View)) {
      drawView(camera, view, /*solving=*/true);
      ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
  }
  // The item buffer costs the solver thread a projection: only while its tab is shown.
  if (itemBufferShown != itemBufferWanted_) solver.setItemBufferWanted(itemBufferShown);
  itemBufferWanted_ = itemBufferShown;
  firstFrame_ = false;
  ImGui::End();
}

bool Panel::beginTab(const char* label, PanelTab tab) {
  const bool select = firstFrame_ && tab == firstTab_;
  return ImGui::BeginTabItem(label, nullptr, select ? ImGuiTabItemFlags_SetSelected : ImGuiTabItemFlags_None);
}

void Panel::drawStateAndCommands(const SolverSnapshot& snapshot, SolverThread& solver) {
  if (!snapshot.error.empty()) failureText(("solve failed: " + snapshot.error).c_str());
  const double unshot = snapshot.ledger.unshotFraction();
  const bool farFromConverged = unshot > kFarFromConvergedUnshot;
  const char* state = snapshot.exhausted                  ? "nothing left to shoot"
                      : snapshot.done && farFromConverged ? "stopped"
                      : snapshot.done                     ? "converged"
                      : snapshot.playing                  ? "playing"
                                                          : "paused";
  if (!snapshot.mesh && snapshot.error.empty()) state = "meshing";
  const SolveOptions& o = snapshot.setup.options;
  if (snapshot.cells)
    ImGui::Text("%s: round %d, %d iterations", state, snapshot.cells->rounds, snapshot.iteration());
  else
    ImGui::Text("%s: iteration %d", state, snapshot.iteration());
  if (o.untilUnshot > 0.0)
    ImGui::TextWrapped("unshot: %.2f%% (until %.2f%%) of %s", 100.0 * unshot, 100.0 * o.untilUnshot,
                       snapshot.ledger.unshotBasis());
  else
    ImGui::TextWrapped("unshot: %.2f%% of %s", 100.0 * unshot, snapshot.ledger.unshotBasis());
  if (snapshot.cells)
    drawCellsState(*snapshot.cells);
  else if (o.until < 1.0)
    ImGui::Text("C = %.4f (until %.3f)", snapshot.convergence(), o.until);
  else
    ImGui::Text("C = %.4f", snapshot.convergence());
  for (const std::string& warning : solveWarnings(snapshot)) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.3f, 1.0f));
    ImGui::TextWrapped("%s", warning.c_str());
    ImGui::PopStyleColor();
  }
  const std::string elements =
      o.subdivide == Subdivide::Off ? "" : fmt::format(" ({} elements)", snapshot.receivers);
  const GridTurn grid = snapshot.summary.grids.principal();
  const std::string turned =
      grid.turned() ? fmt::format(" on a grid turned {:.3g} degrees about {}", grid.degrees(), "xyz"[grid.axis]) : "";
  ImGui::TextWrapped("%s back end, %s %dx%d, k = %d, %zu patches%s%s", toString(o.backend), toString(o.projection),
              o.resolution, o.resolution, o.shooters, snapshot.summary.patches, elements.c_str(), turned.c_str());
  if (ImGui::Button(snapshot.playing ? "Pause" : "Play")) snapshot.playing ? solver.pause() : solver.play();
  ImGui::SameLine();
  if (ImGui::Button(snapshot.cells ? "Round 1" : "Step 1")) solver.step(1);
  ImGui::SameLine();
  if (ImGui::Button("Step N")) solver.step(stepCount_);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(70.0f);
  ImGui::InputInt("N", &stepCount_, 0);
  stepCount_ = std::max(1, stepCount_);
  ImGui::SameLine();
  if (ImGui::Button("Restart")) solver.restart(edited_);
  if (ImGui::Button("Save checkpoint (F5)")) saveCheckpoint(solver);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-FLT_MIN);
  ImGui::InputText("##checkpoint", checkpointPath_.data(), checkpointPath_.size());
  if (snapshot.checkpointFailed)
    failureText(snapshot.checkpointMessage.c_str());
  else if (!snapshot.checkpointMessage.empty())
    note(snapshot.checkpointMessage.c_str());
  const float fps = ImGui::GetIO().Framerate;
  ImGui::TextDisabled("%.1f fps (%.1f ms per frame)", fps, 1e3f / std::max(fps, 1e-3f));
}

void Panel::drawScene(const SolverSnapshot& snapshot) {
  const SceneSummary& s = snapshot.summary;
  if (ImGui::BeginTable("scene", 2)) {
    row("polygons", "%.0f", double(s.polygons));
    row("patches", "%.0f", double(s.patches));
    row("materials", "%.0f", double(s.materials));
    row("emitting polygons", "%.0f", double(s.emitterPolygons));
    row("emitting patches", "%.0f", double(s.emitterPatches));
    row("area m^2", "%.2f", s.totalAreaM2);
    row("emitted W", "%.4g", s.emittedPowerW);
    row("grid cell m", "%.3f", s.cellM);
    row("form-factor cache MiB", "%.0f", snapshot.setup.options.formFactorCacheBytes / 1048576.0);
    ImGui::EndTable();
  }
  const Vec3 size = s.boundsMax - s.boundsMin;
  ImGui::Text("extent %.2f x %.2f x %.2f m", size.x, size.y, size.z);
  if (snapshot.mesh)
    ImGui::Text("display mesh: %zu vertices, %zu triangles", snapshot.mesh->positions.size(),
                snapshot.mesh->indices.size() / 3);
  if (snapshot.effects.empty()) return;
  ImGui::Separator();
  ImGui::Text("effects simulated (--effects %s)", toString(snapshot.setup.options.effects));
  for (const Effect& e : snapshot.effects)
    ImGui::TextWrapped("%s %s: %s", e.name.c_str(), e.on ? "on" : "off", e.reason.c_str());
}

}  // namespace radmesh
