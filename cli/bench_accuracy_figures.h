#pragma once
// What a bench accuracy sweep measures, its points and traces: shared by the sweep (bench_accuracy.cpp)
// and its tables and plots (bench_accuracy_figures.cpp).
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "cli/csv.h"
#include "cli/plot.h"
#include "solver/scene/solve_options.h"

namespace radmesh::cli::accuracy_sweep {

struct Setting {
  Projection projection;
  double ratio;
};

// Where the receivers come from: the patches themselves (off), or elements cut from them.
struct Subdivision {
  Subdivide subdivide = Subdivide::Off;
  double minElementM = 0.0;
  ElementRows rows = ElementRows::Auto;
  bool operator==(const Subdivision&) const = default;
};

struct Point {
  Setting setting;
  int resolution = 0;
  double cellM = 0.0;
  size_t patches = 0;
  Subdivision subdivision;
  size_t elements = 0;  // at the end: adaptive ones split as the solve goes
  double msPerIteration = 0.0;
  double secondsTo95 = -1.0, secondsTo99 = -1.0;  // -1: not reached within the cap
  double error95 = -1.0, error99 = -1.0;
  double imageError95 = -1.0, imageError99 = -1.0;  // 8-bit RMSE against the reference pictures
  double memoryMiB = 0.0;
  double secondsToUnshot = -1.0, errorAtUnshot = -1.0, imageErrorAtUnshot = -1.0;  // --until-unshot
};

// One iteration of the traced solve: what C says beside the true error and the power still unshot.
struct TracePoint {
  int iteration = 0;
  double seconds = 0.0;  // CPU time so far
  double convergence = 0.0;
  double error = 0.0;           // relative RMS error of B - E against the reference
  double unshotFraction = 0.0;  // unshot power over emitted power
};

struct Trace {
  Setting setting;
  int resolution = 0;
  double cellM = 0.0;
  std::vector<TracePoint> points;
};

// Which of (seconds, error) points no other point beats in both (the Pareto front): their
// indices, in order of time. The plots draw the front and label its points.
std::vector<size_t> paretoIndices(const std::vector<std::pair<double, double>>& points);

// Log axes fitted to (seconds, error) points, into plot.settings: the frame, in decades {x0, x1, y0, y1}.
std::array<double, 4> fitLogFrame(const std::vector<std::pair<double, double>>& points, Plot& plot);

// gnuplot commands labelling the points of a fitLogFrame frame, in order of priority, skipping labels
// that would cover one drawn before.
std::vector<std::string> unclutteredLabels(const std::vector<std::pair<double, double>>& points,
                                           const std::vector<std::string>& labels, const std::vector<size_t>& priority,
                                           const std::array<double, 4>& frame);

// A trace's name in the JSON and on the plot.
std::string traceLabel(const std::string& setting, int n, double cellM);

// Every row names the cell of the pictures it was scored against (--reference-cell).
CsvTable pointsTable(const std::vector<Point>& points, double pictureReferenceCellM);
// A row per iteration kept (the plot cannot show them all), a trace after another.
CsvTable tracesTable(const std::vector<Trace>& traces);

}  // namespace radmesh::cli::accuracy_sweep
