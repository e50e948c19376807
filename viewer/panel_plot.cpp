#include "viewer/panel_plot.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace radmesh {

void plotXY(const char* id, std::span<const double> x, std::span<const double> y, const PlotAxes& axes,
            float heightPx, std::span<const double> y2) {
  ImGui::PushID(id);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 size(ImGui::GetContentRegionAvail().x, heightPx);
  ImGui::InvisibleButton("plot", size);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 end(origin.x + size.x, origin.y + size.y);
  draw->AddRectFilled(origin, end, IM_COL32(20, 22, 28, 255));
  draw->AddRect(origin, end, IM_COL32(90, 90, 100, 255));

  const size_t n = std::min(x.size(), y.size());
  const double xMax = n > 0 ? std::max(x[n - 1], 1e-9) : 1.0;
  const double ySpan = std::max(axes.yMax - axes.yMin, 1e-12);
  auto toScreen = [&](double px, double py) {
    const double u = px / xMax;
    const double v = std::clamp((py - axes.yMin) / ySpan, 0.0, 1.0);
    return ImVec2(origin.x + float(u) * size.x, end.y - float(v) * size.y);
  };
  // At most one vertex per pixel column: long solves stay cheap to draw.
  const size_t stride = std::max<size_t>(1, n / std::max<size_t>(1, size_t(size.x)));
  auto line = [&](std::span<const double> values, ImU32 colour) {
    if (values.size() < n) return;
    std::vector<ImVec2> points;
    for (size_t i = 0; i < n; i += stride) points.push_back(toScreen(x[i], values[i]));
    if (n > 0 && (n - 1) % stride != 0) points.push_back(toScreen(x[n - 1], values[n - 1]));
    if (points.size() >= 2) draw->AddPolyline(points.data(), int(points.size()), colour, 0, 1.5f);
    if (points.size() == 1) draw->AddCircleFilled(points[0], 2.5f, colour);  // a resumed solve's first point
  };
  line(y, IM_COL32(110, 200, 255, 255));
  if (!y2.empty()) line(y2, IM_COL32(255, 170, 70, 255));

  char label[96];
  std::snprintf(label, sizeof label, "%g", axes.yMax);
  draw->AddText(ImVec2(origin.x + 3, origin.y + 2), IM_COL32(170, 170, 180, 255), label);
  std::snprintf(label, sizeof label, "%s 0 .. %.4g", axes.xLabel.c_str(), n > 0 ? x[n - 1] : 0.0);
  draw->AddText(ImVec2(origin.x + 3, end.y - ImGui::GetTextLineHeight() - 2), IM_COL32(170, 170, 180, 255),
                label);
  ImGui::PopID();
}

}  // namespace radmesh
