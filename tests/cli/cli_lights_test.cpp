// Lights from the command line: --sun alone lights a scene without emitters through its opening,
// on either back end, and impossible values are refused naming the option.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli/cli_run.h"

namespace radmesh {
namespace {

nlohmann::json solveStats(const std::string& arguments, const std::string& name) {
  const std::string stats = tempPath(name);
  const CommandRun run = radmesh("solve " + arguments + " --stats " + stats);
  EXPECT_EQ(run.exitCode, 0) << run.output;
  std::ifstream in(stats);
  return nlohmann::json::parse(in, nullptr, false);
}

TEST(CliLights, SunAloneLightsAnOpenBoxOnEitherBackEnd) {
  const std::string box = test::dataPath("lights/open_box.gltf").string();
  EXPECT_EQ(radmesh("info " + box).exitCode, 2);  // no emitter without the sun
  // 100000 lux / 179 = 558.66 W/m^2 per channel over the box's 2 x 2 m shadow straight down.
  const nlohmann::json native = solveStats(box + " --sun 180,90 --cell 0.25 --max-iterations 40", "native.json");
  const nlohmann::json mesh = solveStats(box + " --sun 180,90 --cell 0.25 --max-iterations 40 --backend mesh", "mesh.json");
  for (const nlohmann::json* j : {&native, &mesh}) {
    ASSERT_TRUE(j->contains("ledger"));
    const auto& l = (*j)["ledger"];
    EXPECT_NEAR(l["emitted"].get<double>(), 3 * 4.0 * 100000 / 179.0, 1e-6);
    EXPECT_GT(l["absorbed"].get<double>(), 0.45 * l["emitted"].get<double>());  // not black: it falls in
    const double accounted = l["absorbed"].get<double>() + l["unshot"].get<double>() +
                             l["not_captured"].get<double>() + l["escaped"].get<double>();
    EXPECT_NEAR(accounted, l["emitted"].get<double>(), 1e-9 * l["emitted"].get<double>());
    EXPECT_DOUBLE_EQ((*j)["per_iteration"][0]["shot_power"].get<double>(), l["emitted"].get<double>());
  }
}

TEST(CliLights, InfoCountsTheLights) {
  const CommandRun run = radmesh("info " + test::dataPath("lights/three_lights.gltf").string() + " --json");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const auto j = nlohmann::json::parse(run.output.substr(run.output.find('{')));
  EXPECT_EQ(j["lights"], 3);
  EXPECT_EQ(j["emitters"], 0);
}

TEST(CliLights, ImpossibleSunIsRefusedNamingTheOption) {
  for (const char* bad : {"180,0", "180,95", "south,45", "180"}) {
    const CommandRun run = radmesh(std::string("solve furnace --sun ") + bad);
    EXPECT_NE(run.exitCode, 0) << bad;
    EXPECT_NE(run.output.find("--sun"), std::string::npos) << run.output;
  }
  const CommandRun run = radmesh("render furnace --sun 180,-3");
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.output.find("above the horizon"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace radmesh
