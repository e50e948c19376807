#include "viewer/panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "solver/scene/scene_error.h"
#include "viewer/item_buffer_image.h"
#include "viewer/panel_figures.h"
#include "viewer/panel_plot.h"

namespace radmesh {

namespace {

// True while the value changes.
bool sliderDouble(const char* label, double* value, double min, double max, const char* format,
                  ImGuiSliderFlags flags = ImGuiSliderFlags_None) {
  return ImGui::SliderScalar(label, ImGuiDataType_Double, value, &min, &max, format, flags);
}

// A cell counts as settled at this unshot fraction (the target for the camera's room).
constexpr double kCellSettledUnshot = 0.05;

// A solve parameter restarts the solve once the user lets go of it, not at every pixel dragged.
bool released() { return ImGui::IsItemDeactivatedAfterEdit(); }

template <class Enum, size_t N>
bool comboOf(const char* label, Enum* value, const Enum (&choices)[N]) {
  bool changed = false;
  if (ImGui::BeginCombo(label, toString(*value))) {
    for (Enum choice : choices)
      if (ImGui::Selectable(toString(choice), choice == *value)) {
        changed = choice != *value;
        *value = choice;
      }
    ImGui::EndCombo();
  }
  return changed;
}

// A greyed remark that wraps at the panel's edge.
void note(const char* text) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", text);
  ImGui::PopStyleColor();
}

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
  if (!snapshot.error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextWrapped("solve failed: %s", snapshot.error.c_str());
    ImGui::PopStyleColor();
  }
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
    ImGui::Text("unshot power: %.2f%% of the emitted (until %.2f%%)", 100.0 * unshot, 100.0 * o.untilUnshot);
  else
    ImGui::Text("unshot power: %.2f%% of the emitted", 100.0 * unshot);
  if (snapshot.cells)
    drawCellsState(*snapshot.cells);
  else if (o.until < 1.0)
    ImGui::Text("C = %.4f (until %.3f)", snapshot.convergence(), o.until);
  else
    ImGui::Text("C = %.4f", snapshot.convergence());
  if (snapshot.done && farFromConverged) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.3f, 1.0f));
    ImGui::TextWrapped("stopped with %.0f%% of the power unshot: the light is far from converged. Step on, or "
                       "stop on the unshot power (Parameters)",
                       100.0 * unshot);
    ImGui::PopStyleColor();
  }
  ImGui::Text("%s back end, %s %dx%d, k = %d, %zu patches", toString(o.backend), toString(o.projection),
              o.resolution, o.resolution, o.shooters, snapshot.summary.patches);
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
  if (!snapshot.checkpointMessage.empty()) note(snapshot.checkpointMessage.c_str());
  const float fps = ImGui::GetIO().Framerate;
  ImGui::TextDisabled("%.1f fps (%.1f ms per frame)", fps, 1e3f / std::max(fps, 1e-3f));
}

void Panel::drawProgress(const SolverSnapshot& snapshot) {
  std::vector<double> iterations, seconds, c, unshot;
  for (const ConvergencePoint& p : snapshot.curve) {
    iterations.push_back(p.iteration);
    seconds.push_back(p.hostSeconds);
    c.push_back(p.convergence);
    unshot.push_back(p.unshotFraction);
  }
  ImGui::TextUnformatted("C (blue) and unshot power (orange) over iterations");
  plotXY("c-iterations", iterations, c, {"iteration", 0.0, 1.0}, 90.0f, unshot);
  ImGui::TextUnformatted("C and unshot power over host seconds");
  plotXY("c-seconds", seconds, c, {"host s", 0.0, 1.0}, 90.0f, unshot);
  const double lastSeconds = snapshot.curve.size() >= 2
                                 ? snapshot.curve.back().hostSeconds - snapshot.curve.end()[-2].hostSeconds
                                 : snapshot.hostSeconds();
  ImGui::Text("host: %.3f s in all, last %s %.2f ms", snapshot.hostSeconds(), snapshot.cells ? "round" : "iteration",
              1e3 * lastSeconds);
  if (!snapshot.cells)
    ImGui::Text("last shooters: %zu, captured fraction %.4f", snapshot.lastShooters.size(),
                snapshot.lastCapturedFraction);
  drawMachineCost(snapshot);
  ImGui::Separator();
  ImGui::TextUnformatted("energy ledger");
  const Ledger& l = snapshot.ledger;
  const double share = l.emitted > 0.0 ? 100.0 / l.emitted : 0.0;
  if (ImGui::BeginTable("ledger", 3)) {
    auto line = [&](const char* name, double watts) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(name);
      ImGui::TableNextColumn();
      ImGui::Text("%.5g W", watts);
      ImGui::TableNextColumn();
      ImGui::Text("%.2f %%", watts * share);
    };
    line("emitted", l.emitted);
    line("absorbed", l.absorbed);
    line("  by back faces", l.absorbedByBackFaces);
    line("unshot", l.unshot);
    line("not captured", l.notCaptured);
    line("escaped", l.escaped);
    ImGui::EndTable();
  }
  if (l.emitted > 0.0) ImGui::Text("imbalance %.1e", l.imbalance());
}

void Panel::drawMachineCost(const SolverSnapshot& snapshot) {
  if (!snapshot.lastShotStats) {
    note("machine seconds: with a back end that runs on a machine of its own, e.g. the mesh (Parameters)");
    return;
  }
  const ShotStats& shot = *snapshot.lastShotStats;
  const double total = snapshot.curve.empty() ? 0.0 : snapshot.curve.back().machineSeconds;
  ImGui::Text("%s: %.3f s, last shot %.1f ms", shot.machine.c_str(), total, 1e3 * shot.machineSeconds);
  std::vector<double> machineSeconds, c, unshot;
  for (const ConvergencePoint& p : snapshot.curve) {
    machineSeconds.push_back(p.machineSeconds);
    c.push_back(p.convergence);
    unshot.push_back(p.unshotFraction);
  }
  ImGui::Text("C and unshot power over %s seconds", shot.machine.c_str());
  plotXY("c-machine", machineSeconds, c, {"machine s", 0.0, 1.0}, 70.0f, unshot);
  for (const auto& [key, value] : shot.figures.items())
    if (isTable(value)) figureTable(key, value);
}

void Panel::drawShotFigures(const SolverSnapshot& snapshot) {
  if (!snapshot.lastShotStats) {
    note("the last shot's figures (on the mesh: item-buffer depths at stages (a) and (b)): with a back end that "
         "reports them (Parameters)");
    return;
  }
  const nlohmann::json& figures = snapshot.lastShotStats->figures;
  ImGui::TextUnformatted("last shot");  // its numbers, then its histograms, then its groups
  for (const auto& [key, value] : figures.items())
    if (value.is_number()) ImGui::Text("  %s %.6g", key.c_str(), value.get<double>());
  for (const auto& [key, value] : figures.items())
    if (isHistogram(value)) figureHistogram(key, value);
  for (const auto& [key, value] : figures.items())
    if (value.is_object()) figureGroup(key, value);
  // The counts among the numbers, over the iterations that shot.
  for (const auto& [key, value] : figures.items()) {
    if (!value.is_number_integer()) continue;
    std::vector<double> iterations, counts;
    double highest = 1.0;
    for (const ConvergencePoint& p : snapshot.curve) {
      if (!p.shot || !p.shot->figures.contains(key)) continue;
      iterations.push_back(p.iteration);
      counts.push_back(p.shot->figures.at(key).get<double>());
      highest = std::max(highest, counts.back());
    }
    ImGui::Text("%s over iterations", key.c_str());
    plotXY(key.c_str(), iterations, counts, {"iteration", 0.0, highest}, 55.0f);
  }
}

void Panel::drawItemBuffer(const SolverSnapshot& snapshot) {
  if (!snapshot.itemBuffer) {
    note(snapshot.itemBufferShooter >= 0 ? "the back end could not give it" : "shown after the next shot");
    drawShotFigures(snapshot);
    return;
  }
  if (snapshot.itemBuffer != uploadedItemBuffer_) {
    itemBufferTexture_.upload(falseColourImage(*snapshot.itemBuffer));
    uploadedItemBuffer_ = snapshot.itemBuffer;
  }
  const ItemBuffer& buffer = *snapshot.itemBuffer;
  const size_t seen = buffer.items.size() - std::count(buffer.items.begin(), buffer.items.end(), ItemBuffer::kNone);
  ImGui::TextWrapped("the single plane (%dx%d) above patch %d: %.1f%% of its pixels see a patch", buffer.width,
                     buffer.height, snapshot.itemBufferShooter,
                     100.0 * double(seen) / double(std::max<size_t>(1, buffer.items.size())));
  const float side = std::min(ImGui::GetContentRegionAvail().x, 250.0f);
  ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(itemBufferTexture_.id())), ImVec2(side, side));
  note("false colour by patch id");
  drawShotFigures(snapshot);
}

void Panel::drawParameters(SolverThread& solver) {
  SolveOptions& o = edited_.options;
  bool changed = false;
  ImGui::PushItemWidth(200.0f);
  changed |= comboOf("back end", &o.backend, {Backend::Native, Backend::Mesh});
  changed |= comboOf("projection", &o.projection, {Projection::Plane, Projection::Hemicube, Projection::Analytic});
  changed |= comboOf("mapping (mesh)", &o.mapping,
                     {MappingKind::Hierarchical, MappingKind::CutAndStack, MappingKind::Adaptive});
  ImGui::SliderInt("resolution N", &o.resolution, 16, 2048, "%d", ImGuiSliderFlags_Logarithmic);
  changed |= released();
  sliderDouble("ratio", &o.ratio, 0.5, 10.0, "%.2f");
  changed |= released();
  ImGui::SliderInt("shooters k", &o.shooters, 1, 64);
  changed |= released();
  sliderDouble("cell m", &edited_.cellM, 0.02, 2.0, "%.3f", ImGuiSliderFlags_Logarithmic);
  changed |= released();
  ImGui::SliderInt("host threads", &o.threads, 0, 64);
  changed |= released();
  changed |= ImGui::Checkbox("ambient term (display only)", &o.ambient);
  // The stopping rule applies to the solve under way: no restart.
  sliderDouble("until unshot (0: off)", &o.untilUnshot, 0.0, 0.5, "%.3f", ImGuiSliderFlags_Logarithmic);
  bool stoppingRuleChanged = released();
  sliderDouble("until C (1: off)", &o.until, 0.1, 1.0, "%.4f");
  stoppingRuleChanged |= released();
  ImGui::PopItemWidth();
  note("the stopping rule applies to the solve under way; any other change restarts it");
  if (changed || stoppingRuleChanged) {
    try {
      validateOptions(o);
      parameterError_.clear();
      if (changed)
        solver.restart(edited_);
      else
        solver.setStoppingRule(o.until, o.untilUnshot);
    } catch (const OptionError& e) {
      parameterError_ = e.what();
    }
  }
  if (!parameterError_.empty()) ImGui::TextWrapped("not applied: %s", parameterError_.c_str());
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

void Panel::drawView(WalkCamera& camera, ViewSettings& view, bool solving) {
  ImGui::PushItemWidth(200.0f);
  if (sliderDouble("exposure EV", &view.exposureStops, -20.0, 20.0, "%.2f")) view.autoExposure = false;
  ImGui::SameLine();
  if (ImGui::Button("Auto")) view.autoExposure = true;
  ImGui::Checkbox("follow auto exposure", &view.autoExposure);
  if (solving) ImGui::Checkbox("highlight last shooters", &view.highlightShooters);
  if (solving) ImGui::Checkbox("draw only the rooms in sight through doors", &view.cullCells);
  sliderDouble("speed m/s", &camera.speedMps, 0.05, 10.0, "%.2f", ImGuiSliderFlags_Logarithmic);
  sliderDouble("eye height m", &camera.eyeHeightM, 0.02, 3.0, "%.2f");
  sliderDouble("field of view", &camera.fovYDeg, 20.0, 110.0, "%.0f deg");
  ImGui::PopItemWidth();
  note("WASD/arrows walk, Q/E lower/raise, Shift runs");
  note("drag to look around, Esc quits");
}

}  // namespace radmesh
