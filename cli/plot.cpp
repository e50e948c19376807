#include "cli/plot.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace radmesh::cli {

namespace {

// A gnuplot string of any text (a --name's quotes, a path's): double-quoted, its backslashes,
// double quotes and control characters escaped. Single quotes' doubling ('') failed on two in a row.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text)
    if (c == '\\' || c == '"')
      out += std::string{'\\', c};
    else if (static_cast<unsigned char>(c) < 0x20)
      out += fmt::format("\\{:03o}", static_cast<unsigned char>(c));
    else
      out += c;
  return out + "\"";
}

// "set xrange [...]" around a single value, for data spread over none: gnuplot would otherwise warn
// of an empty range on every plot of a one-point sweep. Empty where the data spreads.
std::string rangeAroundOneValue(const char* axis, const std::vector<double>& values, bool log) {
  if (values.empty()) return "";
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  if (*lo != *hi) return "";
  const double v = *lo;
  if (log) return v > 0.0 ? fmt::format("set {}range [{:.9g}:{:.9g}]\n", axis, v / 10.0, v * 10.0) : "";  // decades labelled
  const double half = v == 0.0 ? 1.0 : 0.5 * std::abs(v);
  return fmt::format("set {}range [{:.9g}:{:.9g}]\n", axis, v - half, v + half);
}

}  // namespace

bool gnuplotInstalled() { return std::system("command -v gnuplot > /dev/null 2>&1") == 0; }

void requireGnuplot() {
  if (!gnuplotInstalled())
    throw std::runtime_error("gnuplot is not installed, so there is nothing to draw with (fix: apt-get install gnuplot-nox)");
}

bool drawPlot(const Plot& plot, const std::string& png) {
  if (!gnuplotInstalled()) {
    fmt::print(stderr, "radmesh: gnuplot is not installed, so {} was not drawn (apt-get install gnuplot-nox)\n", png);
    return false;
  }
  std::string script = "set terminal pngcairo size 1000,700 noenhanced font 'DejaVu Sans,11'\n";
  // The x label ends in an empty line: gnuplot sets the key below right under it, touching.
  script += fmt::format("set output {}\nset title {}\nset xlabel {} . \"\\n\"\nset ylabel {}\n", quoted(png),
                        quoted(plot.title), quoted(plot.xLabel), quoted(plot.yLabel));
  script += "set grid\nset key below\n";
  if (plot.logX) script += "set logscale x\n";
  if (plot.logY) script += "set logscale y\n";
  std::vector<double> xs, ys;
  for (const Series& series : plot.series)
    for (const auto& [x, y] : series.points) {
      xs.push_back(x);
      ys.push_back(y);
    }
  script += rangeAroundOneValue("x", xs, plot.logX) + rangeAroundOneValue("y", ys, plot.logY);
  for (const std::string& setting : plot.settings) script += setting + "\n";
  script += "plot ";
  for (size_t i = 0; i < plot.series.size(); ++i)
    script += fmt::format("{}'-' with {} title {}", i ? ", " : "", plot.series[i].style, quoted(plot.series[i].title));
  script += "\n";
  for (const Series& s : plot.series) {
    for (const auto& [x, y] : s.points) script += fmt::format("{:.9g} {:.9g}\n", x, y);
    script += "e\n";
  }
  // The script goes down a pipe: nothing is left beside the PNG. A gnuplot that stops early fails the
  // write below instead of killing radmesh with SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  // Its standard output is not ours: a PNG it could not write to a file would come out there.
  FILE* gnuplot = popen("gnuplot > /dev/null", "w");
  if (!gnuplot) throw std::runtime_error("cannot start gnuplot to draw " + png);
  const bool written = std::fputs(script.c_str(), gnuplot) >= 0;
  if (pclose(gnuplot) != 0 || !written) throw std::runtime_error("gnuplot failed to draw " + png + " (its message is above)");
  return true;
}

}  // namespace radmesh::cli
