// `radmesh bench accuracy`'s tables and plots: the CSVs of the points and traces, and the figures of
// docs/accuracy.md drawn from them (also by `radmesh plot accuracy`), apart from the sweep that measures.
#include "cli/bench_accuracy_figures.h"

#include <fmt/core.h>

#include <algorithm>

#include "cli/bench.h"
#include "cli/plot.h"

namespace radmesh::cli {

using namespace accuracy_sweep;

namespace accuracy_sweep {

std::string traceLabel(const std::string& setting, int n, double cellM) {
  return fmt::format("{} {}x{}, cell {}", setting, n, n, cellM);
}

namespace {

// The plot cannot show more iterations than it has pixels: the CSV and the plot keep this many of each
// trace, evenly spaced, the last, and the first at each stop docs/accuracy.md quotes; the JSON keeps every one.
constexpr size_t kTraceRows = 300;
constexpr double kConvergenceStops[] = {0.95, 0.99, 0.999};
constexpr double kUnshotStops[] = {0.10, 0.05, 0.01};

std::vector<char> keptTraceRows(const std::vector<TracePoint>& points) {
  const size_t n = points.size();
  std::vector<char> kept(n, 0);
  if (n == 0) return kept;
  for (size_t i = 0; i < n; i += (n + kTraceRows - 1) / kTraceRows) kept[i] = 1;
  kept[n - 1] = 1;
  auto keepFirst = [&](auto reached) {
    const auto it = std::find_if(points.begin(), points.end(), reached);
    if (it != points.end()) kept[it - points.begin()] = 1;
  };
  for (double c : kConvergenceStops) keepFirst([c](const TracePoint& p) { return p.convergence >= c; });
  for (double u : kUnshotStops) keepFirst([u](const TracePoint& p) { return p.unshotFraction <= u; });
  return kept;
}

}  // namespace

CsvTable pointsTable(const std::vector<Point>& points, double pictureReferenceCellM) {
  CsvTable t{.columns = {"projection", "ratio", "resolution", "cell_m", "patches", "ms_per_iteration", "seconds_to_95",
              "seconds_to_99", "error_at_95", "error_at_99", "image_rmse_at_95", "image_rmse_at_99", "memory_mib",
              "subdivide", "min_element", "elements", "seconds_to_unshot", "error_at_unshot", "image_rmse_at_unshot",
              "element_rows", "reference_cell_m"}};
  for (const Point& p : points)
    t.rows.push_back({toString(p.setting.projection), fmt::format("{}", p.setting.ratio), std::to_string(p.resolution),
                      fmt::format("{}", p.cellM), std::to_string(p.patches), fmt::format("{:.6g}", p.msPerIteration),
                      fmt::format("{:.6g}", p.secondsTo95), fmt::format("{:.6g}", p.secondsTo99),
                      fmt::format("{:.6g}", p.error95), fmt::format("{:.6g}", p.error99),
                      fmt::format("{:.4g}", p.imageError95), fmt::format("{:.4g}", p.imageError99),
                      fmt::format("{:.4g}", p.memoryMiB), toString(p.subdivision.subdivide),
                      fmt::format("{}", p.subdivision.minElementM), std::to_string(p.elements),
                      fmt::format("{:.6g}", p.secondsToUnshot), fmt::format("{:.6g}", p.errorAtUnshot),
                      fmt::format("{:.4g}", p.imageErrorAtUnshot), toString(p.subdivision.rows),
                      fmt::format("{}", pictureReferenceCellM)});
  return t;
}

CsvTable tracesTable(const std::vector<Trace>& traces) {
  CsvTable t{.columns = {"projection", "ratio", "resolution", "cell_m", "iteration", "seconds", "convergence", "error",
              "unshot_fraction"}};
  for (const Trace& trace : traces) {
    const std::vector<char> kept = keptTraceRows(trace.points);
    for (size_t i = 0; i < trace.points.size(); ++i) {
      if (!kept[i]) continue;
      const TracePoint& p = trace.points[i];
      // C to 9 digits: the plot shows 1 - C down to 1e-5.
      t.rows.push_back({toString(trace.setting.projection), fmt::format("{}", trace.setting.ratio),
                        std::to_string(trace.resolution), fmt::format("{}", trace.cellM), std::to_string(p.iteration),
                        fmt::format("{:.4g}", p.seconds), fmt::format("{:.9g}", p.convergence),
                        fmt::format("{:.4g}", p.error), fmt::format("{:.4g}", p.unshotFraction)});
    }
  }
  return t;
}

}  // namespace accuracy_sweep

namespace {

// Points no other point beats in both time and error, in order of time.
std::vector<std::pair<double, double>> paretoFront(std::vector<std::pair<double, double>> points) {
  std::sort(points.begin(), points.end());
  std::vector<std::pair<double, double>> front;
  for (const auto& pt : points)
    if (front.empty() || pt.second < front.back().second) front.push_back(pt);
  return front;
}

// The front in black after the series, when there is anything to draw: a plot with no point (a
// sweep of elements alone has no patch rows for the same-mesh plot) is not drawn at all.
void addParetoFront(Plot& plot, const std::vector<std::pair<double, double>>& all) {
  if (!all.empty()) plot.series.push_back({"Pareto front", paretoFront(all), "lines lw 3 lc rgb 'black'"});
}

void drawUnlessEmpty(const Plot& plot, const std::string& path, std::vector<std::string>& drawn) {
  if (!plot.series.empty() && drawPlot(plot, path)) drawn.push_back(path);
}

std::string rowSetting(const CsvTable& t, size_t row) { return settingLabel(t.text(row, "projection"), t.number(row, "ratio")); }

// Tables written before the subdivide axis have patches only.
bool hasSubdivide(const CsvTable& t) { return std::ranges::find(t.columns, "subdivide") != t.columns.end(); }
std::string rowSubdivide(const CsvTable& t, size_t row) { return hasSubdivide(t) ? t.text(row, "subdivide") : "off"; }

// Error at C = 0.99 against the time to reach it, a series per setting and cell, Pareto front in black.
Plot errorVersusTime(const std::string& title, const std::string& errorLabel, const CsvTable& points,
                     const std::string& errorColumn) {
  Plot plot{.title = title, .xLabel = "seconds to C = 0.99", .yLabel = errorLabel, .logX = true, .logY = true};
  std::vector<std::pair<double, double>> all;
  for (size_t row = 0; row < points.rows.size(); ++row) {
    const double seconds = points.number(row, "seconds_to_99"), error = points.number(row, errorColumn);
    if (seconds <= 0 || error < 0 || rowSubdivide(points, row) != "off") continue;
    const std::string name = fmt::format("{} cell {}", rowSetting(points, row), points.number(row, "cell_m"));
    auto it = std::find_if(plot.series.begin(), plot.series.end(), [&](const Series& s) { return s.title == name; });
    if (it == plot.series.end()) it = plot.series.insert(plot.series.end(), Series{name, {}, "linespoints"});
    // Log axes: an exact zero is drawn at the floor.
    it->points.emplace_back(seconds, std::max(error, 1e-9));
    all.push_back(it->points.back());
  }
  addParetoFront(plot, all);
  return plot;
}

// A point's --element-rows when it was not the default (older CSVs have no such column).
std::string rowsNote(const CsvTable& points, size_t row) {
  if (std::ranges::find(points.columns, "element_rows") == points.columns.end()) return "";
  const std::string rows = points.text(row, "element_rows");
  return rows == "auto" ? "" : " " + rows;
}

// The subdivide axis: picture error against time, a series per subdivide mode, each point labelled
// with its cell and element size, the Pareto front in black. At --until-unshot when it was measured.
Plot subdivisionPlot(const std::string& sceneName, const CsvTable& points) {
  bool atUnshot = false;
  for (size_t row = 0; row < points.rows.size(); ++row) atUnshot |= points.number(row, "seconds_to_unshot") > 0;
  const std::string secondsColumn = atUnshot ? "seconds_to_unshot" : "seconds_to_99";
  const std::string errorColumn = atUnshot ? "image_rmse_at_unshot" : "image_rmse_at_99";
  const std::string stop = atUnshot ? "the unshot stop" : "C = 0.99";
  Plot plot{.title = "Picture error against time to " + stop + ", patches against elements: " + sceneName,
            .xLabel = "CPU seconds to " + stop + " (one thread)", .yLabel = "RMSE of the pictures, 8-bit levels",
            .logX = true, .logY = true};
  const std::vector<std::pair<std::string, std::string>> modes = {
      {"off", "patches (off)"}, {"uniform", "uniform elements"}, {"adaptive", "adaptive elements"}};
  std::vector<std::pair<double, double>> all;
  for (size_t m = 0; m < modes.size(); ++m) {
    Series series{modes[m].second, {}, fmt::format("points pt {} ps 2", 5 + 2 * m)};
    for (size_t row = 0; row < points.rows.size(); ++row) {
      const double seconds = points.number(row, secondsColumn), error = points.number(row, errorColumn);
      if (seconds <= 0 || error < 0 || points.text(row, "subdivide") != modes[m].first) continue;
      series.points.emplace_back(seconds, std::max(error, 1e-9));
      all.push_back(series.points.back());
      const std::string setting = fmt::format("{} {}", rowSetting(points, row), points.text(row, "resolution"));
      const std::string what = modes[m].first == "off"
                                   ? fmt::format("{} cell {}", setting, points.text(row, "cell_m"))
                                   : fmt::format("{} cell {} el {}{}", setting, points.text(row, "cell_m"),
                                                 points.text(row, "min_element"), rowsNote(points, row));
      plot.settings.push_back(fmt::format("set label \"{}\" at {},{} offset 1,0.5 font ',8'", what, seconds,
                                          std::max(error, 1e-9)));
    }
    if (!series.points.empty()) plot.series.push_back(series);
  }
  addParetoFront(plot, all);
  return plot;
}

}  // namespace

std::string settingLabel(const std::string& projection, double ratio) {
  return projection == "plane" ? fmt::format("plane r{}", ratio) : projection;
}

std::vector<std::string> drawAccuracyFigures(const std::string& stem, const std::string& sceneName) {
  std::vector<std::string> drawn;
  const std::string writer = "bench accuracy --out-dir DIR --name NAME";
  const CsvTable points = readCsv(stem + ".csv", writer), traces = readCsv(stem + "-traces.csv", writer);
  drawUnlessEmpty(errorVersusTime("Error against time to C=0.99, same mesh: " + sceneName,
                                  "relative RMS error of B - E", points, "error_at_99"),
                  stem + "-error-vs-time.png", drawn);
  // Not without the viewer, which the pictures need.
  drawUnlessEmpty(errorVersusTime("Picture error against time to C=0.99, across meshes: " + sceneName,
                                  "RMSE of the pictures, 8-bit levels", points, "image_rmse_at_99"),
                  stem + "-image-error-vs-time.png", drawn);
  // Each setting's true error and unshot power; 1 - C of the first, which is what C promises.
  Plot conv{.title = "What convergence C says against the true error: " + sceneName, .xLabel = "iteration",
            .yLabel = "fraction", .logY = true};
  Series remaining{"", {}, "lines dt 2"};
  std::string previous;  // a trace's rows are consecutive
  for (size_t row = 0; row < traces.rows.size(); ++row) {
    const std::string label = traceLabel(rowSetting(traces, row), int(traces.number(row, "resolution")),
                                         traces.number(row, "cell_m"));
    if (label != previous) {
      conv.series.push_back({"error of B - E, " + label, {}, "lines lw 2"});
      conv.series.push_back({"unshot / emitted, " + label, {}, "lines"});
      if (previous.empty()) remaining.title = "1 - C, " + label;
      previous = label;
    }
    const double iteration = traces.number(row, "iteration");
    conv.series[conv.series.size() - 2].points.emplace_back(iteration, std::max(traces.number(row, "error"), 1e-9));
    conv.series.back().points.emplace_back(iteration, std::max(traces.number(row, "unshot_fraction"), 1e-9));
    if (conv.series.size() == 2)
      remaining.points.emplace_back(iteration, std::max(1.0 - traces.number(row, "convergence"), 1e-9));
  }
  if (!remaining.points.empty()) conv.series.push_back(remaining);
  drawUnlessEmpty(conv, stem + "-error-vs-convergence.png", drawn);  // traces follow off rows only
  if (hasSubdivide(points)) drawUnlessEmpty(subdivisionPlot(sceneName, points), stem + "-subdivide.png", drawn);
  return drawn;
}

}  // namespace radmesh::cli
