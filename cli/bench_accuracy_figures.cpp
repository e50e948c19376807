// `radmesh bench accuracy`'s tables and plots: the CSVs of the points and traces, and the figures of
// docs/accuracy.md drawn from them (also by `radmesh plot accuracy`), apart from the sweep that measures.
#include "cli/bench_accuracy_figures.h"

#include <fmt/core.h>

#include <stdexcept>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <numeric>

#include "cli/bench.h"
#include "cli/plot.h"
#include "solver/io/output_path.h"
#include "solver/scene/scene_error.h"

namespace radmesh::cli {

using namespace accuracy_sweep;

namespace accuracy_sweep {

std::vector<size_t> paretoIndices(const std::vector<std::pair<double, double>>& points) {
  std::vector<size_t> order(points.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return points[a] < points[b]; });
  std::vector<size_t> front;
  for (size_t i : order)
    if (front.empty() || points[i].second < points[front.back()].second) front.push_back(i);
  return front;
}

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

// The front in black after the series, when there is anything to draw: a plot with no point (a
// sweep of elements alone has no patch rows for the same-mesh plot) is not drawn at all.
void addParetoFront(Plot& plot, const std::vector<std::pair<double, double>>& all) {
  if (all.empty()) return;
  Series front{"Pareto front", {}, "lines lw 3 lc rgb 'black'"};
  for (size_t i : paretoIndices(all)) front.points.push_back(all[i]);
  plot.series.push_back(front);
}

void drawUnlessEmpty(const Plot& plot, const std::string& path, std::vector<std::string>& drawn) {
  if (!plot.series.empty() && drawPlot(plot, path)) drawn.push_back(path);
}

std::string rowSetting(const CsvTable& t, size_t row) { return settingLabel(t.text(row, "projection"), t.number(row, "ratio")); }

// Tables written before the subdivide axis have patches only.
bool hasSubdivide(const CsvTable& t) { return std::ranges::find(t.columns, "subdivide") != t.columns.end(); }
std::string rowSubdivide(const CsvTable& t, size_t row) { return hasSubdivide(t) ? t.text(row, "subdivide") : "off"; }

}  // namespace

namespace accuracy_sweep {

// The frame gnuplot draws within its 1000 x 700 picture (the key below), and a label at font 9.
constexpr double kFrameWidthPx = 894.0, kFrameHeightPx = 576.0, kLabelCharPx = 6.0, kLabelHeightPx = 12.0;

// Log axes fitted to the points: time to whole decades, error to a quarter beyond its extremes,
// ticked at 1, 1.5, 2, 3, 5 and 7 times powers of ten so that a range under a decade reads. Returns
// the frame in decades: {x0, x1, y0, y1}.
std::array<double, 4> fitLogFrame(const std::vector<std::pair<double, double>>& points, Plot& plot) {
  double xLow = points[0].first, xHigh = xLow, yLow = points[0].second, yHigh = yLow;
  for (const auto& [x, y] : points) {
    xLow = std::min(xLow, x), xHigh = std::max(xHigh, x);
    yLow = std::min(yLow, y), yHigh = std::max(yHigh, y);
  }
  const std::array<double, 4> frame = {std::floor(std::log10(xLow)), std::ceil(std::log10(xHigh) + 1e-9),
                                       std::log10(yLow / 1.25), std::log10(yHigh * 1.25)};
  std::string ticks;  // over more than two decades gnuplot's own, a decade apart, read better
  for (double decade = std::floor(frame[2]); frame[3] - frame[2] <= 2.0 && decade <= frame[3]; ++decade)
    for (double mantissa : {1.0, 1.5, 2.0, 3.0, 5.0, 7.0})
      if (const double tick = mantissa * std::pow(10.0, decade); std::log10(tick) >= frame[2] && std::log10(tick) <= frame[3])
        ticks += fmt::format("{}{:g}", ticks.empty() ? "" : ", ", tick);
  plot.settings.push_back(fmt::format("set xrange [{:g}:{:g}]", std::pow(10.0, frame[0]), std::pow(10.0, frame[1])));
  plot.settings.push_back(fmt::format("set yrange [{:g}:{:g}]", std::pow(10.0, frame[2]), std::pow(10.0, frame[3])));
  if (!ticks.empty()) plot.settings.push_back("set ytics (" + ticks + ")");
  return frame;
}

// The labels to draw, in order of priority, as gnuplot commands: each a character right of its
// point (left of it where the frame would cut it), half a line above it or else a line below, and
// skipped where both would cover a label drawn before it.
std::vector<std::string> unclutteredLabels(const std::vector<std::pair<double, double>>& points,
                                           const std::vector<std::string>& labels, const std::vector<size_t>& priority,
                                           const std::array<double, 4>& frame) {
  struct Box {
    double left, right, bottom, top;
  };
  std::vector<Box> drawn;
  std::vector<std::string> commands;
  for (size_t i : priority) {
    const double x = (std::log10(points[i].first) - frame[0]) / (frame[1] - frame[0]) * kFrameWidthPx + kLabelCharPx;
    const double y = (std::log10(points[i].second) - frame[2]) / (frame[3] - frame[2]) * kFrameHeightPx;
    const double width = kLabelCharPx * static_cast<double>(labels[i].size());
    // Left of the point where the frame's right edge would cut it.
    const bool left = x + width > kFrameWidthPx;
    const double begin = left ? x - 2.0 * kLabelCharPx - width : x;
    for (const double lines : {0.5, -1.0}) {
      const double middle = y + lines * kLabelHeightPx;
      const Box box{begin, begin + width, middle - kLabelHeightPx / 2, middle + kLabelHeightPx / 2};
      if (std::ranges::any_of(drawn, [&](const Box& d) {
            return box.left < d.right && d.left < box.right && box.bottom < d.top && d.bottom < box.top;
          }))
        continue;
      drawn.push_back(box);
      commands.push_back(fmt::format("set label \"{}\" at {},{} {} offset {},{} font ',9'", labels[i], points[i].first,
                                     points[i].second, left ? "right" : "left", left ? -1 : 1, lines));
      break;
    }
  }
  return commands;
}

}  // namespace accuracy_sweep

namespace {

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
  if (!all.empty()) fitLogFrame(all, plot);
  addParetoFront(plot, all);
  return plot;
}

// A point's --element-rows when it was not the default (older CSVs have no such column).
std::string rowsNote(const CsvTable& points, size_t row) {
  if (std::ranges::find(points.columns, "element_rows") == points.columns.end()) return "";
  const std::string rows = points.text(row, "element_rows");
  return rows == "auto" ? "" : " " + rows;
}

// The subdivide axis: picture error against time, a series per subdivide mode, the Pareto front in
// black. Its points are labelled with their resolution, cell and element size, and so is each
// mode's point of least error (the patch mesh elements are measured against, and the best of each
// kind of element); a label on every point would cover the others. At --until-unshot when it was
// measured.
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
  bool oneSetting = true;
  for (size_t row = 1; row < points.rows.size(); ++row) oneSetting &= rowSetting(points, row) == rowSetting(points, 0);
  std::vector<std::pair<double, double>> all;
  std::vector<std::string> labels;
  std::vector<size_t> best;  // per mode drawn, its point of least error
  for (size_t m = 0; m < modes.size(); ++m) {
    Series series{modes[m].second, {}, fmt::format("points pt {} ps 2", 5 + 2 * m)};
    size_t modeBest = SIZE_MAX;
    for (size_t row = 0; row < points.rows.size(); ++row) {
      const double seconds = points.number(row, secondsColumn), error = points.number(row, errorColumn);
      if (seconds <= 0 || error < 0 || points.text(row, "subdivide") != modes[m].first) continue;
      series.points.emplace_back(seconds, std::max(error, 1e-9));
      if (modeBest == SIZE_MAX || error < all[modeBest].second) modeBest = all.size();
      all.push_back(series.points.back());
      const std::string n = points.text(row, "resolution");
      const std::string setting = oneSetting ? n + "²" : fmt::format("{} {}²", rowSetting(points, row), n);
      labels.push_back(modes[m].first == "off"
                           ? fmt::format("{}, cell {}", setting, points.text(row, "cell_m"))
                           : fmt::format("{}, cell {}, el {}{}", setting, points.text(row, "cell_m"),
                                         points.text(row, "min_element"), rowsNote(points, row)));
    }
    if (!series.points.empty()) plot.series.push_back(series), best.push_back(modeBest);
  }
  // Each mode's best first, then the front from its most accurate end.
  std::vector<size_t> priority = best;
  const std::vector<size_t> front = paretoIndices(all);
  for (auto i = front.rbegin(); i != front.rend(); ++i)
    if (std::ranges::find(priority, *i) == priority.end()) priority.push_back(*i);
  if (!all.empty())
    for (std::string& label : unclutteredLabels(all, labels, priority, fitLogFrame(all, plot)))
      plot.settings.push_back(std::move(label));
  if (oneSetting && !points.rows.empty()) plot.title += " (" + rowSetting(points, 0) + ")";
  addParetoFront(plot, all);
  return plot;
}

}  // namespace

std::string settingLabel(const std::string& projection, double ratio) {
  return projection == "plane" ? fmt::format("plane r{}", ratio) : projection;
}

std::vector<std::string> drawAccuracyFigures(const std::string& stem, const std::string& sceneName,
                                             const std::string& pngStem) {
  std::vector<std::string> drawn;
  const std::string writer = "bench accuracy --out-dir DIR --name NAME";
  const CsvTable points = readCsv(stem + ".csv", writer), traces = readCsv(stem + "-traces.csv", writer);
  // A header alone drew one plot and skipped the rest (the traces may be empty: a sweep of elements alone).
  if (points.rows.empty())
    throw OptionError(points.path + ": a header and no rows: nothing to draw (" + writer + " writes rows)");
  // The inputs first: one missing or empty leaves no folder behind.
  makeOutputFolder("--out-dir", std::filesystem::path(pngStem).parent_path().string());
  drawUnlessEmpty(errorVersusTime("Error against time to C=0.99, same mesh: " + sceneName,
                                  "relative RMS error of B - E", points, "error_at_99"),
                  pngStem + "-error-vs-time.png", drawn);
  // Not without the viewer, which the pictures need.
  drawUnlessEmpty(errorVersusTime("Picture error against time to C=0.99, across meshes: " + sceneName,
                                  "RMSE of the pictures, 8-bit levels", points, "image_rmse_at_99"),
                  pngStem + "-image-error-vs-time.png", drawn);
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
  drawUnlessEmpty(conv, pngStem + "-error-vs-convergence.png", drawn);  // traces follow off rows only
  if (hasSubdivide(points)) drawUnlessEmpty(subdivisionPlot(sceneName, points), pngStem + "-subdivide.png", drawn);
  return drawn;
}

}  // namespace radmesh::cli
