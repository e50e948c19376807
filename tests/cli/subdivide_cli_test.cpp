// --subdivide uniform and --min-element as a user runs them: the counts --stats, info and the bake
// agree on, and the combinations refused.
#include <gtest/gtest.h>

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
  EXPECT_EQ(j["elements"].get<double>(), summary["elements"].get<double>());
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

TEST(CliSubdivide, AdaptiveSplitsAndStatsCountTheElements) {
  const std::string stats = tempPath("adaptive-stats.json");
  const CommandRun run = radmesh("solve cornell --cell 0.2 --subdivide adaptive --min-element 0.025 --split-contrast 0.4 "
                                 "--resolution 64 --max-iterations 10 --stats " + stats);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  std::ifstream in(stats);
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["subdivide"], "adaptive");
  EXPECT_EQ(j["split_contrast"], 0.4);
  EXPECT_EQ(j["split_shadows"], true);
  EXPECT_GT(j["elements"].get<int>(), j["patches"].get<int>());  // some elements split
  EXPECT_LE(j["ledger"]["imbalance"].get<double>(), 1e-12);
  EXPECT_NE(run.output.find(std::to_string(j["elements"].get<int>()) + " elements"), std::string::npos) << run.output;
}

TEST(CliSubdivide, WhatIsNotBuiltYetIsRefusedNamingTheFlag) {
  CommandRun run = radmesh("solve cornell --subdivide adaptive");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--subdivide adaptive splits elements down to --min-element"), std::string::npos)
      << run.output;
  run = radmesh("solve cornell --subdivide adaptive --min-element 0.1 --backend mesh");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("not built on the mesh back end"), std::string::npos) << run.output;
  run = radmesh("solve cornell --subdivide adaptive --min-element 0.1 --split-shadows maybe");
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.output.find("--split-shadows"), std::string::npos) << run.output;
  run = radmesh("solve cornell --subdivide uniform --min-element -1");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--min-element -1"), std::string::npos) << run.output;
  run = radmesh("solve two-rooms --subdivide uniform --cells auto");
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.output.find("--subdivide and --cells auto"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace radmesh
