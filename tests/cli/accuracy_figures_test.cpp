#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>

#include "cli/bench_accuracy_figures.h"
#include "cli/plot.h"
#include "tests/cli/cli_run.h"
#ifdef RADMESH_HAS_VIEWER
#include "viewer/image.h"
#endif

namespace radmesh::cli::accuracy_sweep {
namespace {

// The front holds the points no other beats in both time and error, in order of time; a point
// equalled in error by a faster one, or beaten in both, is off it.
TEST(AccuracyFigures, TheParetoFrontIsThePointsNoneBeatsInOrderOfTime) {
  const std::vector<std::pair<double, double>> points = {
      {5.0, 4.0},   // 0: the most accurate
      {1.0, 20.0},  // 1: the fastest
      {2.0, 9.0},   // 2: on the front
      {3.0, 9.0},   // 3: as accurate as 2, slower
      {4.0, 12.0},  // 4: beaten by 2 in both
      {2.5, 6.0},   // 5: on the front
  };
  EXPECT_EQ(paretoIndices(points), (std::vector<size_t>{1, 2, 5, 0}));
  EXPECT_TRUE(paretoIndices({}).empty());
}

// Under two decades of error the axis is ticked at 1, 1.5, 2, 3, 5 and 7 times powers of ten; over
// more, gnuplot's decades are left alone. Time runs over whole decades.
TEST(AccuracyFigures, TheLogFrameTicksAnErrorRangeUnderTwoDecades) {
  Plot narrow;
  const std::array<double, 4> frame = fitLogFrame({{0.5, 4.0}, {30.0, 8.0}}, narrow);
  EXPECT_EQ(frame[0], -1.0);
  EXPECT_EQ(frame[1], 2.0);
  EXPECT_NEAR(frame[2], std::log10(4.0 / 1.25), 1e-12);
  EXPECT_NEAR(frame[3], std::log10(8.0 * 1.25), 1e-12);
  EXPECT_NE(std::ranges::find(narrow.settings, "set ytics (5, 7, 10)"), narrow.settings.end());
  Plot wide;
  fitLogFrame({{1.0, 1e-9}, {2.0, 0.5}}, wide);
  EXPECT_TRUE(std::ranges::none_of(wide.settings, [](const std::string& s) { return s.starts_with("set ytics"); }));
}

// A label goes right of its point, or left of it where the frame's right edge would cut it; a label
// that would cover one drawn before goes a line lower, or is left out.
TEST(AccuracyFigures, LabelsStayInsideTheFrameAndOffEachOther) {
  Plot plot;
  const std::vector<std::pair<double, double>> points = {{2.0, 5.0}, {2.0, 5.0}, {2.0, 5.0}, {95.0, 5.0}};
  const std::vector<std::string> labels = {"a", "b", "c", "256², cell 0.381"};
  const std::array<double, 4> frame = fitLogFrame(points, plot);
  const std::vector<std::string> commands = unclutteredLabels(points, labels, {0, 1, 2, 3}, frame);
  ASSERT_EQ(commands.size(), 3u);
  EXPECT_EQ(commands[0], "set label \"a\" at 2,5 left offset 1,0.5 font ',9'");
  EXPECT_EQ(commands[1], "set label \"b\" at 2,5 left offset 1,-1 font ',9'");
  EXPECT_EQ(commands[2], "set label \"256², cell 0.381\" at 95,5 right offset -1,0.5 font ',9'");
}

// A --name of quotes ('' broke the gnuplot script: "unexpected or unrecognized token"), a
// backslash or a line break is drawn into its figures' titles and file names as given.
TEST(AccuracyFigures, ANameOfQuotesIsDrawn) {
  if (!gnuplotInstalled()) GTEST_SKIP() << "gnuplot is not installed (apt-get install gnuplot-nox)";
  const std::string dir = std::filesystem::path(tempPath("figures.png")).parent_path().string();
  for (const std::string name : {"''", "it's \"q\" \\ \nnext"}) {
    const CommandRun run = radmesh("bench accuracy furnace --cells 0.5 --projections hemicube --resolutions 16 "
                                   "--reference-resolution 32 --out-dir " + dir + " --name '" +
                                   std::regex_replace(name, std::regex("'"), "'\\''") + "'");
    EXPECT_EQ(run.exitCode, 0) << name << ": " << run.output;
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + name + "-error-vs-time.png")) << name << ": " << run.output;
  }
}

#ifdef RADMESH_HAS_VIEWER
// Below the frame come the tick labels, the x label and the key, each apart from the next: the key
// of two rows sat right under the label, touching it.
TEST(AccuracyFigures, TheXLabelStandsApartFromTheKeyBelowIt) {
  if (!gnuplotInstalled()) GTEST_SKIP() << "gnuplot is not installed (apt-get install gnuplot-nox)";
  Plot plot{"a figure", "CPU seconds to the unshot stop (one thread)", "RMSE", true, true, {}, {}};
  for (int i = 0; i < 6; ++i)  // six series: a key of two rows
    plot.series.push_back({"a series named at some length " + std::to_string(i), {{1.0 + i, 5.0 + i}}, "points"});
  const std::string png = tempPath("figure.png");
  ASSERT_TRUE(drawPlot(plot, png));
  const Image image = readPng(png);
  const auto inked = [&](int y, int x0, int x1) {
    int n = 0;
    for (int x = x0; x < x1; ++x) {
      const std::uint8_t* p = &image.rgba[4 * (static_cast<size_t>(y) * image.width + x)];
      n += std::min({p[0], p[1], p[2]}) < 160;
    }
    return n;
  };
  // The frame's bottom edge: the lowest row inked across most of the width.
  int frame = image.height - 1;
  while (frame > 0 && inked(frame, 0, image.width) < image.width / 2) --frame;
  ASSERT_GT(frame, image.height / 2);
  // Below it, bands of inked rows: tick labels, the x label and the key's rows, each a line of text
  // at most (11-point type: 15 rows of pixels here). The label and the key touching make one band
  // of two lines (28 rows).
  std::vector<int> heights;
  for (int y = frame + 2, run = 0; y < image.height; ++y) {
    const bool ink = inked(y, 0, image.width) > 0;
    if (ink) ++run;
    if ((!ink || y + 1 == image.height) && run > 0) {
      heights.push_back(run);
      run = 0;
    }
  }
  ASSERT_GE(heights.size(), 4u) << "tick labels, the x label and the key's rows";
  for (size_t i = 0; i < heights.size(); ++i) EXPECT_LE(heights[i], 20) << "band " << i << " of " << heights.size();
}
#endif

}  // namespace
}  // namespace radmesh::cli::accuracy_sweep
