#include "cli/plot.h"

#include <fmt/core.h>
#include <fmt/ostream.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace radmesh::cli {

namespace {

std::string quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

}  // namespace

bool drawPlot(const Plot& plot, const std::string& png) {
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) {
    fmt::print(stderr, "radmesh: gnuplot is not installed, so {} was not drawn (apt-get install gnuplot-nox)\n", png);
    return false;
  }
  const std::filesystem::path script = std::filesystem::path(png).replace_extension(".gnuplot");
  std::ofstream out(script);
  if (!out) throw std::runtime_error(script.string() + ": cannot write the plot script");
  fmt::print(out, "set terminal pngcairo size 1000,700 noenhanced font 'DejaVu Sans,11'\n");
  fmt::print(out, "set output {}\nset title {}\nset xlabel {}\nset ylabel {}\n", quoted(png), quoted(plot.title),
             quoted(plot.xLabel), quoted(plot.yLabel));
  fmt::print(out, "set grid\nset key below\n");
  if (plot.logX) fmt::print(out, "set logscale x\n");
  if (plot.logY) fmt::print(out, "set logscale y\n");
  fmt::print(out, "plot ");
  for (size_t i = 0; i < plot.series.size(); ++i)
    fmt::print(out, "{}'-' with {} title {}", i ? ", " : "", plot.series[i].style, quoted(plot.series[i].title));
  fmt::print(out, "\n");
  for (const Series& s : plot.series) {
    for (const auto& [x, y] : s.points) fmt::print(out, "{:.9g} {:.9g}\n", x, y);
    fmt::print(out, "e\n");
  }
  out.close();
  std::string shellPath;  // single-quoted for the shell
  for (char c : script.string()) shellPath += c == '\'' ? std::string("'\\''") : std::string(1, c);
  const std::string command = "gnuplot '" + shellPath + "' 2>&1";
  if (std::system(command.c_str()) != 0) throw std::runtime_error("gnuplot failed on " + script.string());
  return true;
}

}  // namespace radmesh::cli
