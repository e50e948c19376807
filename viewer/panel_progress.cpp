// The panel's Progress and Item buffer tabs: what the solve has done so far, and its last shot.
#include <imgui.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "viewer/item_buffer_image.h"
#include "viewer/panel.h"
#include "viewer/panel_figures.h"
#include "viewer/panel_plot.h"
#include "viewer/panel_widgets.h"

namespace radmesh {

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
    // A light's power on the model's outside (the sun on a roof): part of escaped and of the back faces' share.
    if (l.lightOutside > 0.0) line("  never came in", l.lightOutside);
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
  // The figure starts its own line: wrapping breaks after a '.', and cut "100.0%" in two.
  ImGui::TextWrapped("the single plane (%dx%d) above patch %d:\n%.1f%% of its pixels see a patch", buffer.width,
                     buffer.height, snapshot.itemBufferShooter,
                     100.0 * double(seen) / double(std::max<size_t>(1, buffer.items.size())));
  const float side = std::min(ImGui::GetContentRegionAvail().x, 250.0f);
  ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(itemBufferTexture_.id())), ImVec2(side, side));
  note("false colour by patch id");
  drawShotFigures(snapshot);
}

}  // namespace radmesh
