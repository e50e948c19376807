#pragma once
// Figures people would rather look at than read, drawn to PNG by gnuplot (Debian's gnuplot-nox).
#include <string>
#include <utility>
#include <vector>

namespace radmesh::cli {

struct Series {
  std::string title;
  std::vector<std::pair<double, double>> points;
  std::string style = "linespoints";  // any gnuplot `with` style: lines, points, linespoints, steps
};

struct Plot {
  std::string title;
  std::string xLabel;
  std::string yLabel;
  bool logX = false;
  bool logY = false;
  std::vector<Series> series{};
  std::vector<std::string> settings{};  // more gnuplot commands after the defaults, e.g. "set xrange [50:100]"
};

// Throws std::runtime_error, naming the package, when gnuplot is not installed: for commands whose
// only work is drawing.
void requireGnuplot();

// Writes `png` (1000x700, the key below the plot). Throws std::runtime_error naming gnuplot's failure; returns false,
// saying why on stderr, when gnuplot is not installed.
bool drawPlot(const Plot& plot, const std::string& png);

}  // namespace radmesh::cli
