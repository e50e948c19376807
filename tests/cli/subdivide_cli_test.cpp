// --subdivide uniform and --min-element as a user runs them: the counts --stats, info and the bake
// agree on, and the combinations refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli/cli_run.h"

namespace radmesh {
namespace {

TEST(CliSubdivide, StatsInfoAndTheBakeCountTheSameElements) {
  const CommandRun info = radmesh("info cornell --cell 0.1 --min-element 0.05 --json");
  ASSERT_EQ(info.exitCode, 0) << info.output;
  const auto summary = nlohmann::json::parse(info.output);
  const std::string stats = tempPath("subdivide-stats.json"), bake = tempPath("subdivide.glb");
  const CommandRun run = radmesh("solve cornell --cell 0.1 --subdivide uniform --min-element 0.05 --resolution 64 "
                                 "--max-iterations 30 --stats " + stats + " --out " + bake);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  std::ifstream in(stats);
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["patches"], summary["patches"]);
  EXPECT_EQ(j["elements"], summary["elements"]);
  EXPECT_TRUE(summary["elements"].is_number_integer()) << "a count, as --stats gives it (info wrote 1460.0)";
  EXPECT_GT(j["elements"].get<int>(), 2 * j["patches"].get<int>());
  EXPECT_EQ(j["subdivide"], "uniform");
  EXPECT_EQ(j["min_element"], 0.05);
  EXPECT_LE(j["ledger"]["imbalance"].get<double>(), 1e-12);
  EXPECT_NE(run.output.find(std::to_string(j["elements"].get<int>()) + " elements"), std::string::npos) << run.output;
  // The bake shows the elements: at least a triangle each.
  const CommandRun baked = radmesh("info " + bake + " --json");
  ASSERT_EQ(baked.exitCode, 0) << baked.output;
  EXPECT_GE(nlohmann::json::parse(baked.output)["triangles"].get<int>(), j["elements"].get<int>());
  // Off: the same keys, as many elements as patches.
  const CommandRun off = radmesh("solve cornell --cell 0.1 --resolution 64 --max-iterations 2 --stats " + stats);
  ASSERT_EQ(off.exitCode, 0) << off.output;
  std::ifstream again(stats);
  const auto o = nlohmann::json::parse(again);
  EXPECT_EQ(o["elements"], o["patches"]);
  EXPECT_EQ(o["subdivide"], "off");
}

// On both back ends (on the mesh the PEs take the split elements): --stats counts the elements,
// and on the mesh the iterations that split charge the elements' moves to the router.
TEST(CliSubdivide, AdaptiveSplitsAndStatsCountTheElements) {
  for (const std::string backend : {"native", "mesh"}) {
    SCOPED_TRACE(backend);
    const std::string stats = tempPath(backend + "-adaptive-stats.json");
    const CommandRun run = radmesh("solve cornell --backend " + backend + (backend == "mesh" ? " --pe-grid 16x16" : "") + " --cell 0.2 --subdivide adaptive "
                                   "--min-element 0.05 --split-contrast 0.4 --resolution 64 --max-iterations 6 --stats " + stats);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    std::ifstream in(stats);
    const auto j = nlohmann::json::parse(in);
    EXPECT_EQ(j["backend"], backend);
    EXPECT_EQ(j["subdivide"], "adaptive");
    EXPECT_EQ(j["split_contrast"], 0.4);
    EXPECT_EQ(j["split_shadows"], true);
    EXPECT_GT(j["elements"].get<int>(), j["patches"].get<int>());  // some elements split
    // Each split turns one element into four: the iterations' counts add up to the elements made.
    int splits = 0;
    for (const auto& iteration : j["per_iteration"]) splits += iteration["elements_split"].get<int>();
    EXPECT_EQ(j["elements"].get<int>(), j["patches"].get<int>() + 3 * splits);
    EXPECT_LE(j["ledger"]["imbalance"].get<double>(), 1e-12);
    EXPECT_NE(run.output.find(std::to_string(j["elements"].get<int>()) + " elements"), std::string::npos) << run.output;
    if (backend != "mesh") continue;
    std::int64_t moved = 0;
    for (const auto& iteration : j["per_iteration"])
      for (const auto& phase : iteration["phases"])
        if (phase["name"] == "element split") moved += phase["op_counts"]["router"]["messages"].get<std::int64_t>();
    EXPECT_GT(moved, 0);
  }
}

// --cells auto with elements: the stats count them in all and per cell, the bake shows them, the
// ledgers balance.
TEST(CliSubdivide, CellsAutoWithElementsBakesAndCountsThem) {
  const std::string stats = tempPath("cells-elements.json"), bake = tempPath("cells-elements.glb");
  const CommandRun run = radmesh("solve two-rooms --cells auto --subdivide uniform --cell 0.75 --resolution 32 "
                                 "--until-unshot 0.2 --quiet --stats " + stats + " --out " + bake);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  std::ifstream in(stats);
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["subdivide"], "uniform");
  EXPECT_EQ(j["elements"].get<int>(), 4 * j["patches"].get<int>());  // --min-element 0: every patch in four
  int perCell = 0;
  for (const auto& cell : j["per_cell"]) {
    EXPECT_EQ(cell["elements"].get<int>(), 4 * cell["patches"].get<int>()) << cell["name"];
    EXPECT_LE(cell["ledger"]["imbalance"].get<double>(), 1e-9) << cell["name"];
    perCell += cell["elements"].get<int>();
  }
  EXPECT_EQ(perCell, j["elements"].get<int>());
  EXPECT_LE(j["ledger"]["imbalance"].get<double>(), 1e-9);
  EXPECT_NE(run.output.find(std::to_string(j["elements"].get<int>()) + " elements"), std::string::npos) << run.output;
  const CommandRun baked = radmesh("info " + bake + " --json");
  ASSERT_EQ(baked.exitCode, 0) << baked.output;
  EXPECT_GE(nlohmann::json::parse(baked.output)["triangles"].get<int>(), j["elements"].get<int>());
}

// Without --min-element adaptive subdivision splits down to a quarter of the cell (docs/accuracy.md),
// in a whole solve and a cells solve alike, and says so.
TEST(CliSubdivide, AdaptiveWithoutAMinElementTakesAQuarterOfTheCell) {
  for (const std::string cells : {"off", "auto"}) {
    const std::string stats = tempPath("adaptive-default-" + cells + ".json");
    const CommandRun run = radmesh("solve cornell --cell 0.1 --subdivide adaptive --cells " + cells +
                                   " --resolution 32 --max-iterations 3 --quiet --stats " + stats);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("min element 0.025 m, a quarter of the cell (--min-element sets it)"), std::string::npos)
        << run.output;
    const nlohmann::json j = readJson(stats);
    EXPECT_EQ(j["min_element"], 0.025);
  }
  const CommandRun given = radmesh("solve cornell --cell 0.1 --subdivide adaptive --min-element 0.05 --resolution 32 "
                                   "--max-iterations 3 --quiet");
  ASSERT_EQ(given.exitCode, 0) << given.output;
  EXPECT_EQ(given.output.find("min element"), std::string::npos) << given.output;
}

TEST(CliSubdivide, ImpossibleOptionsAreRefusedNamingTheFlag) {
  CommandRun run = radmesh("solve cornell --subdivide adaptive --min-element 0.1 --split-shadows maybe");
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.output.find("--split-shadows"), std::string::npos) << run.output;
  run = radmesh("solve cornell --subdivide uniform --min-element -1");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--min-element -1"), std::string::npos) << run.output;
  run = radmesh("solve cornell --subdivide uniform --backend mesh --element-rows share");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--element-rows share is the native back end's"), std::string::npos) << run.output;
  run = radmesh("solve cornell --subdivide uniform --element-rows pixels");
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.output.find("--element-rows 'pixels' is unknown"), std::string::npos) << run.output;
  // An element flag without its elements used to be dropped without a word.
  run = radmesh("solve cornell --min-element 0.1");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--min-element shapes the elements, and --subdivide is off: add --subdivide uniform or "
                            "adaptive (docs/accuracy.md), or leave --min-element out"),
            std::string::npos)
      << run.output;
  run = radmesh("render cornell --subdivide uniform --split-contrast 0.2 --out x.png");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--split-contrast shapes adaptive elements, and --subdivide is uniform"), std::string::npos)
      << run.output;
}

// The subdivide axis of `bench accuracy`: off on every cell, uniform and adaptive on the coarsest,
// once per element size. The furnace (a 1 m box) meshes to 6 patches at 1 m and 24 at 0.5 m. A value
// listed twice is measured once: the 16 and uniform given twice, and adaptive's 0, a quarter of the
// cell, being its 0.25.
TEST(CliSubdivide, BenchAccuracyMeasuresEachSubdivisionOnItsCells) {
  const std::string dir = tempPath("accuracy"), json = tempPath("furnace.json");
  const CommandRun run = radmesh(
      "bench accuracy furnace --cells 1,0.5 --resolutions 16,16 --projections hemicube --reference-resolution 32 "
      "--subdivide off,uniform,adaptive,uniform --min-element 0,0.5 --adaptive-min-element 0.25,0 --until-unshot 0.05 "
      "--threads 1 --out-dir " + dir + " --json " + json);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  std::ifstream in(json);
  const auto j = nlohmann::json::parse(in);
  const auto& points = j["points"];
  ASSERT_EQ(points.size(), 5u);  // cell 1: off, uniform 0, uniform 0.5, adaptive 0.25; cell 0.5: off
  const std::vector<std::string> subdivide = {"off", "uniform", "uniform", "adaptive", "off"};
  const std::vector<double> cells = {1, 1, 1, 1, 0.5}, minElements = {0, 0, 0.5, 0.25, 0};
  const std::vector<int> patches = {6, 6, 6, 6, 24};
  for (size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(points[i]["subdivide"], subdivide[i]) << i;
    EXPECT_EQ(points[i]["cell"].get<double>(), cells[i]) << i;
    EXPECT_EQ(points[i]["min_element"].get<double>(), minElements[i]) << i;
    EXPECT_EQ(points[i]["patches"].get<int>(), patches[i]) << i;
    EXPECT_EQ(points[i]["projection"], "hemicube") << i;
    EXPECT_EQ(points[i]["element_rows"], "auto") << i;
    // Every point reached both stops (-1: not reached).
    EXPECT_GT(points[i]["seconds_to_99"].get<double>(), 0.0) << i;
    EXPECT_GT(points[i]["seconds_to_unshot"].get<double>(), 0.0) << i;
    EXPECT_GE(points[i]["error_at_unshot"].get<double>(), 0.0) << i;
  }
  // Uniform: four elements a patch at 0, and 0.5 m cuts 1 m patches in four too; off: the patches.
  EXPECT_EQ(points[0]["elements"].get<int>(), 6);
  EXPECT_EQ(points[1]["elements"].get<int>(), 24);
  EXPECT_EQ(points[2]["elements"].get<int>(), 24);
  EXPECT_EQ(points[4]["elements"].get<int>(), 24);
  // Adaptive starts from the patches and each split adds three elements, down to 0.25 m (96 at most).
  const int adaptive = points[3]["elements"].get<int>();
  EXPECT_GE(adaptive, 6);
  EXPECT_LE(adaptive, 96);
  EXPECT_EQ((adaptive - 6) % 3, 0);
  // The CSV has a row per point and the new columns after the old ones.
  std::ifstream csv(dir + "/furnace.csv");
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header.substr(header.find("memory_mib")),
            "memory_mib,subdivide,min_element,elements,seconds_to_unshot,error_at_unshot,image_rmse_at_unshot,"
            "element_rows,reference_cell_m");
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 5);
}

// --element-rows: uniform and adaptive once per value, each named in the JSON.
TEST(CliSubdivide, BenchAccuracyMeasuresEachElementRows) {
  const std::string json = tempPath("furnace-rows.json");
  const CommandRun run = radmesh(
      "bench accuracy furnace --cells 1 --resolutions 16 --projections hemicube --reference-resolution 32 "
      "--subdivide off,uniform --min-element 0.5 --element-rows rasterise,share --threads 1 --json " + json);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  std::ifstream in(json);
  const auto points = nlohmann::json::parse(in)["points"];
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(points[0]["subdivide"], "off");
  EXPECT_EQ(points[1]["element_rows"], "rasterise");
  EXPECT_EQ(points[2]["element_rows"], "share");
  EXPECT_EQ(points[2]["elements"].get<int>(), 24);
  EXPECT_NE(run.output.find("uniform 0.5 share"), std::string::npos) << run.output;
}

// A sweep of one point spreads over no range: its plots are drawn around the point, without
// gnuplot's "empty x range" warnings (one per axis and plot until 2026-12-04).
TEST(CliSubdivide, BenchAccuracyOfOnePointDrawsItsPlotsWithoutWarnings) {
  if (!gnuplotInstalled()) GTEST_SKIP() << "gnuplot is not installed (scripts/install-deps.sh installs it)";
  const std::string dir = tempPath("accuracy-one-point");
  const CommandRun run = radmesh(
      "bench accuracy furnace --cells 1 --resolutions 16 --projections hemicube --reference-resolution 32 "
      "--threads 1 --out-dir " + dir);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  for (const std::string plot : {"error-vs-time", "image-error-vs-time", "error-vs-convergence"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/furnace-" + plot + ".png")) << plot;
  EXPECT_EQ(run.output.find("Warning:"), std::string::npos) << run.output;
}

// A sweep of elements alone has no patch row for the same-mesh plots: they are left out, and the
// subdivide plot is drawn (before 2026-12-03 gnuplot was handed an empty plot and the bench failed).
TEST(CliSubdivide, BenchAccuracyOfElementsAloneDrawsTheSubdividePlot) {
  const std::string dir = tempPath("accuracy-elements");
  const CommandRun run = radmesh(
      "bench accuracy furnace --cells 1 --resolutions 16 --projections hemicube --reference-resolution 32 "
      "--subdivide uniform --threads 1 --out-dir " + dir);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_TRUE(std::filesystem::exists(dir + "/furnace.csv"));
  EXPECT_EQ(std::filesystem::exists(dir + "/furnace-subdivide.png"), gnuplotInstalled()) << run.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/furnace-error-vs-time.png"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/furnace-error-vs-convergence.png"));
  // `plot accuracy` draws it again from the table, named by its stem or by the CSV itself.
  std::filesystem::remove(dir + "/furnace-subdivide.png");
  const CommandRun redrawn = radmesh("plot accuracy " + dir + "/furnace.csv");
  ASSERT_EQ(redrawn.exitCode, gnuplotInstalled() ? 0 : 1) << redrawn.output;  // drawing is all it does
  EXPECT_EQ(std::filesystem::exists(dir + "/furnace-subdivide.png"), gnuplotInstalled()) << redrawn.output;
  EXPECT_EQ(redrawn.output.find("drew " + dir + "/furnace-subdivide.png\n") != std::string::npos, gnuplotInstalled())
      << redrawn.output;  // it used to say nothing
}

TEST(CliSubdivide, BenchAccuracyRefusesASubdivisionItCannotRun) {
  CommandRun run = radmesh("bench accuracy furnace --cells 1 --subdivide adaptive --adaptive-min-element -1");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--min-element -1 is out of range"), std::string::npos) << run.output;
  run = radmesh("bench accuracy furnace --cells 1,0.5 --subdivide uniform --subdivide-cells 0.3");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--subdivide-cells 0.3"), std::string::npos) << run.output;
  run = radmesh("bench accuracy furnace --cells 1 --subdivide sometimes");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--subdivide 'sometimes' is unknown"), std::string::npos) << run.output;
  run = radmesh("bench accuracy furnace --cells 1 --projections analytic");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--projections 'analytic'"), std::string::npos) << run.output;
}

// A cells solve with adaptive elements and a point light (it crashed before 2026-12-02): the
// light's direct light splits the elements before the first round, as the whole solve's first
// iteration does, and the element counts come out the same.
TEST(CliSubdivide, AdaptiveCellsSolveWithAPointLightSplitsAsTheWholeSolve) {
  const std::string box = test::dataPath("lights/point_box.gltf").string();
  const std::string options = " --subdivide adaptive --min-element 0.1 --resolution 64 --threads 1 --quiet --stats ";
  const std::string cellsStats = tempPath("cells.json"), wholeStats = tempPath("whole.json");
  const CommandRun cells = radmesh("solve " + box + " --cells auto" + options + cellsStats);
  ASSERT_EQ(cells.exitCode, 0) << cells.output;
  const CommandRun whole = radmesh("solve " + box + options + wholeStats);
  ASSERT_EQ(whole.exitCode, 0) << whole.output;
  const nlohmann::json c = readJson(cellsStats), w = readJson(wholeStats);
  EXPECT_GT(w["elements"].get<int>(), w["patches"].get<int>());
  EXPECT_EQ(c["elements"], w["elements"]);
}

}  // namespace
}  // namespace radmesh
