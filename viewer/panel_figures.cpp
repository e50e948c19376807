#include "viewer/panel_figures.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <vector>

namespace radmesh {

bool isHistogram(const nlohmann::json& value) {
  return value.is_array() && !value.empty() &&
         std::all_of(value.begin(), value.end(), [](const auto& v) { return v.is_number(); });
}

bool isTable(const nlohmann::json& value) {
  return value.is_array() && !value.empty() &&
         std::all_of(value.begin(), value.end(), [](const auto& v) { return v.is_object(); });
}

void figureHistogram(const std::string& key, const nlohmann::json& counts) {
  ImGui::Text("%s, 0 .. %zu", key.c_str(), counts.empty() ? size_t{0} : counts.size() - 1);
  std::vector<float> values;
  for (const auto& v : counts) values.push_back(v.get<float>());
  ImGui::PushID(key.c_str());
  ImGui::PlotHistogram("##histogram", values.data(), int(values.size()), 0, nullptr, 0.0f, FLT_MAX,
                       ImVec2(ImGui::GetContentRegionAvail().x, 50.0f));
  ImGui::PopID();
}

void figureTable(const std::string& key, const nlohmann::json& rows) {
  // Words and numbers only: a column of objects (a stage's op counts) would show blank.
  std::vector<std::string> columns;
  for (const auto& [column, value] : rows.front().items())
    if (value.is_string() || value.is_number()) columns.push_back(column);
  std::stable_partition(columns.begin(), columns.end(),
                        [&](const std::string& c) { return rows.front()[c].is_string(); });
  // Each column as wide as its longest entry, scrolled sideways where the panel is narrower: a
  // first column stretched into what the others left was cut to "shooter se".
  const ImGuiStyle& style = ImGui::GetStyle();
  const float height = ImGui::GetTextLineHeightWithSpacing() * float(rows.size() + 1) + style.ScrollbarSize +
                       2.0f * style.CellPadding.y;
  if (!ImGui::BeginTable(key.c_str(), int(columns.size()), ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX,
                         ImVec2(0.0f, height)))
    return;
  for (const std::string& c : columns) ImGui::TableSetupColumn(c.c_str());
  ImGui::TableHeadersRow();
  for (const nlohmann::json& r : rows) {
    ImGui::TableNextRow();
    for (const std::string& c : columns) {
      ImGui::TableNextColumn();
      const nlohmann::json cell = r.value(c, nlohmann::json());
      if (cell.is_string()) ImGui::TextUnformatted(cell.get<std::string>().c_str());
      if (cell.is_number()) ImGui::Text("%.4g", cell.get<double>());
    }
  }
  ImGui::EndTable();
}

void figureGroup(const std::string& key, const nlohmann::json& group) {
  if (!ImGui::TreeNode(key.c_str())) return;
  for (const auto& [k, v] : group.items()) {
    if (v.is_number()) ImGui::Text("%s %.6g", k.c_str(), v.get<double>());
    if (v.is_object()) figureGroup(k, v);
  }
  ImGui::TreePop();
}

}  // namespace radmesh
