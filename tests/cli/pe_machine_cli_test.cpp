// --pe-grid and --pe-memory: the mesh back end's machine from the command line, and the refusals.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <numeric>
#include <string>

#include "tests/cli/cli_run.h"

namespace radmesh {
namespace {

int sum(const nlohmann::json& histogram) {
  const std::vector<int> counts = histogram.get<std::vector<int>>();
  return std::accumulate(counts.begin(), counts.end(), 0);
}

TEST(PeMachineCli, SolveRunsOnTheGridItIsGiven) {
  const std::string stats = tempPath("stats.json");
  const CommandRun run = radmesh("solve cornell --backend mesh --preset paper --pe-grid 128x128 --pe-memory 8 "
                                 "--max-iterations 2 --threads 1 --quiet --stats " + stats);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const nlohmann::json j = readJson(stats);
  EXPECT_EQ(j["pe_grid"], "128x128");
  EXPECT_EQ(j["pe_memory_kb"], 8);
  // Every PE of the machine is in the depth histograms, and none used more than it has.
  const nlohmann::json& first = j["per_iteration"][0];
  EXPECT_EQ(sum(first["depth_a_hist"]), 128 * 128);
  EXPECT_EQ(sum(first["depth_b_hist"]), 128 * 128);
  EXPECT_LE(first["op_counts"]["memory_high_water_bytes"].get<int>(), 8 * 1024);
}

TEST(PeMachineCli, TheDefaultMachineIsTheMp1s) {
  const std::string stats = tempPath("stats.json");
  const CommandRun run = radmesh("solve cornell --backend mesh --preset paper --max-iterations 1 --threads 1 --quiet --stats " + stats);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const nlohmann::json j = readJson(stats);
  EXPECT_EQ(j["pe_grid"], "64x64");
  EXPECT_EQ(j["pe_memory_kb"], 16);
  EXPECT_EQ(sum(j["per_iteration"][0]["depth_a_hist"]), 64 * 64);
}

TEST(PeMachineCli, BenchSolveTakesTheMachine) {
  const std::string json = tempPath("bench.json");
  const CommandRun run = radmesh("bench solve cornell --backend mesh --projections plane --resolutions 64 "
                                 "--max-iterations 2 --pe-grid 128x64 --pe-memory 32 --json " + json);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("PE grid 128x64, 32 KB a PE"), std::string::npos) << run.output;
  EXPECT_EQ(readJson(json)["rows"].size(), 1u);
}

// Without --projections the mesh back end times the plane alone, as `solve` takes it; a hemicube
// asked of it is refused before any row is timed (before 2026-12-03 the plane's rows ran first).
TEST(PeMachineCli, BenchSolveOnTheMeshTimesThePlaneAndRefusesTheHemicubeFirst) {
  const std::string json = tempPath("bench.json");
  CommandRun run = radmesh("bench solve cornell --backend mesh --resolutions 32,64 --max-iterations 2 --json " + json);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const nlohmann::json rows = readJson(json)["rows"];
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) EXPECT_EQ(row["projection"], "plane");
  run = radmesh("bench solve cornell --backend mesh --projections plane,hemicube --resolutions 64 --max-iterations 2");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  // It names the bench's own flags: --projection is not one of them.
  EXPECT_NE(run.output.find("--projections hemicube is native only: give --projections plane or --backend native"),
            std::string::npos)
      << run.output;
  EXPECT_EQ(run.output.find("ms/iteration"), std::string::npos) << run.output;
  run = radmesh("bench solve cornell --resolutions 64,8 --max-iterations 2");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--resolutions 8 is out of range"), std::string::npos) << run.output;
}

TEST(PeMachineCli, BadMachinesExit2NamingTheOptionAndTheFix) {
  struct Case {
    std::string arguments, expected;
  };
  const Case cases[] = {
      {"solve cornell --backend mesh --pe-grid 48x64", "--pe-grid 48x64 is not a mesh the machine can sort on"},
      {"solve cornell --backend mesh --pe-grid 64", "--pe-grid '64' is not COLSxROWS"},
      {"solve cornell --backend mesh --pe-grid 4096x4096", "powers of two from 2 to 1024, e.g. 64x64"},
      {"solve cornell --backend mesh --pe-memory 0", "--pe-memory 0 is out of range: give each PE's memory in KB"},
      {"bench solve cornell --backend mesh --pe-grid 100x100", "--pe-grid 100x100 is not a mesh"},
      // Too little memory for the patches themselves: the machine's error, with the flags that fix it.
      {"solve office --backend mesh --preset paper --pe-grid 2x2 --pe-memory 1 --max-iterations 1",
       "budget is 1024 bytes. Fix: give each PE more memory (a larger --pe-memory KB), spread the work over more PEs (a "
       "larger --pe-grid), or give it less to hold (a smaller --resolution or fewer --shooters)"},
      // Too many shooters at once for the PEs: the fix names the flag the user raised.
      {"solve cornell --backend mesh --shooters 1846 --max-iterations 3 --quiet", "fewer --shooters"},
  };
  for (const Case& c : cases) {
    const CommandRun run = radmesh(c.arguments);
    EXPECT_EQ(run.exitCode, 2) << c.arguments << "\n" << run.output;
    EXPECT_NE(run.output.find(c.expected), std::string::npos) << c.arguments << "\n" << run.output;
  }
}

// The grid orders the form factors' sums and its counts are the saved state: a checkpoint resumes
// on its own grid only, whichever side has the MP-1's.
TEST(PeMachineCli, ACheckpointResumesOnItsOwnGridOnly) {
  const std::string checkpoint = tempPath("grid.ckpt");
  const std::string solve = "solve cornell --backend mesh --preset paper --threads 1 --quiet ";
  ASSERT_EQ(radmesh(solve + "--pe-grid 128x128 --max-iterations 2 --checkpoint " + checkpoint).exitCode, 0);
  const CommandRun elsewhere = radmesh(solve + "--max-iterations 3 --resume " + checkpoint);
  EXPECT_EQ(elsewhere.exitCode, 2) << elsewhere.output;
  EXPECT_NE(elsewhere.output.find("--pe-grid 128x128 there, 64x64 here"), std::string::npos) << elsewhere.output;
  const CommandRun bigger = radmesh(solve + "--pe-grid 256x256 --max-iterations 3 --resume " + checkpoint);
  EXPECT_NE(bigger.output.find("--pe-grid 128x128 there, 256x256 here"), std::string::npos) << bigger.output;
  EXPECT_EQ(radmesh(solve + "--pe-grid 128x128 --max-iterations 3 --resume " + checkpoint).exitCode, 0);
}

#ifdef RADMESH_HAS_VIEWER
TEST(PeMachineCli, RenderRefusesABadGridBeforeSolving) {
  const CommandRun run = radmesh("render cornell --backend mesh --pe-grid 3x3 --out " + tempPath("cornell.png"));
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--pe-grid 3x3"), std::string::npos) << run.output;
}
#endif

}  // namespace
}  // namespace radmesh
