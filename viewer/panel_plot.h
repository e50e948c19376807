#pragma once
// A line plot of y over an arbitrary, increasing x (ImGui's PlotLines spaces x evenly, which would
// hide how the convergence curve behaves against time).
#include <span>
#include <string>

namespace radmesh {

struct PlotAxes {
  std::string xLabel;  // e.g. "iteration", "host s"
  double yMin = 0.0;
  double yMax = 1.0;
};

// Draws y (blue) and, when given, y2 (orange) over x in the current ImGui window at the cursor,
// full width, `heightPx` tall.
void plotXY(const char* id, std::span<const double> x, std::span<const double> y, const PlotAxes& axes,
            float heightPx = 110.0f, std::span<const double> y2 = {});

}  // namespace radmesh
