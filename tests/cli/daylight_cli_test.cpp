// Daylight and the default cell as a user meets them: a room lit only by --sky through one window
// converges and renders; a closed one is refused; without --cell the cell follows the scene.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli/cli_run.h"
#ifdef RADMESH_HAS_VIEWER
#include "viewer/image.h"
#endif

namespace radmesh {
namespace {

const std::string kRoom = (test::dataPath("daylight") / "room_one_window.mgf").string();
const std::string kClosedRoom = (test::dataPath("daylight") / "room_closed.mgf").string();
// A 1.2 x 1.2 m vertical window under a uniform sky of 10 000 lux, the ground black: half the
// horizontal illuminance, at 179 lm/W, summed over R, G, B.
const double kWindowW = 3.0 * 1.44 * 5000.0 / 179.0;

TEST(Cli, SkyLightsARoomThroughOneWindow) {
  const CommandRun info = radmesh("info " + kRoom + " --sky 10000 --json");
  ASSERT_EQ(info.exitCode, 0) << info.output;
  const auto j = nlohmann::json::parse(info.output.substr(info.output.find('{')));  // after the up-axis note
  EXPECT_EQ(j["emitters"], 1);
  EXPECT_NEAR(j["emitted_power"].get<double>(), kWindowW, 1e-9 * kWindowW);
  EXPECT_EQ(j["material_list"].back()["name"], "sky (opening 1)");
  ASSERT_EQ(j["daylight"].size(), 1u) << j["daylight"].dump();
  EXPECT_NE(j["daylight"][0].get<std::string>().find("through 1 opening(s), 1.44 m^2"), std::string::npos);

  const std::string stats = tempPath("stats.json");
  const CommandRun solve = radmesh("solve " + kRoom + " --sky 10000 --resolution 64 --quiet --stats " + stats);
  ASSERT_EQ(solve.exitCode, 0) << solve.output;
  const auto s = nlohmann::json::parse(std::ifstream(stats));
  EXPECT_LE(s["unshot_fraction"].get<double>(), 0.01);
  const auto& l = s["ledger"];
  EXPECT_NEAR(l["emitted"].get<double>(), kWindowW, 1e-9 * kWindowW);
  const double accounted = l["absorbed"].get<double>() + l["unshot"].get<double>() +
                           l["not_captured"].get<double>() + l["escaped"].get<double>();
  EXPECT_NEAR(accounted, l["emitted"].get<double>(), 1e-9 * kWindowW);
  // The window closes the room: nothing escapes, what leaves through the window is absorbed by it.
  EXPECT_EQ(l["escaped"].get<double>(), 0.0);

  // The sky is emitter patches: the cells solve takes it as it is (a room of one cell).
  const std::string cellsStats = tempPath("cells.json");
  const CommandRun cells = radmesh("solve " + kRoom + " --sky 10000 --resolution 64 --cells auto --quiet --stats " + cellsStats);
  ASSERT_EQ(cells.exitCode, 0) << cells.output;
  const auto c = nlohmann::json::parse(std::ifstream(cellsStats));
  EXPECT_NEAR(c["ledger"]["emitted"].get<double>(), kWindowW, 1e-9 * kWindowW);
  EXPECT_LE(c["ledger"]["imbalance"].get<double>(), 1e-9);
  EXPECT_LE(c["unshot_fraction"].get<double>(), 0.01);
  EXPECT_NEAR(c["ledger"]["absorbed"].get<double>(), l["absorbed"].get<double>(), 0.01 * kWindowW);

#ifdef RADMESH_HAS_VIEWER
  const std::string png = tempPath("room.png");
  // At a fixed exposure (white at B = 1 W/m^2), so that the bound measures the light: the room
  // under 10 000 lux measured a mean of 203 of 255, under 1000 lux 69.
  const CommandRun render = radmesh("render " + kRoom +
                                    " --sky 10000 --sky-model cie-overcast --resolution 64 --size 160x120 --exposure 0 "
                                    "--quiet --out " + png);
  ASSERT_EQ(render.exitCode, 0) << render.output;
  const Image picture = readPng(png);
  double sum = 0.0;
  for (size_t i = 0; i < picture.rgba.size(); ++i)
    if (i % 4 != 3) sum += picture.rgba[i];
  const double mean = sum / (3.0 * picture.width * picture.height);
  EXPECT_GT(mean, 150.0) << "the room is dark in " << png;
#endif
}

// The sky in the window used to stop the sun: with both, all the sunlight was booked as never
// entering. The sun's light that enters must be the same with the sky as without it, and the two
// emit their sum, in one solve and cell by cell.
TEST(Cli, TheSunShinesThroughTheSkysWindow) {
  for (const std::string cells : {"off", "auto"}) {
    auto ledger = [&](const std::string& daylight) {
      const std::string stats = tempPath("sun-sky.json");
      const CommandRun run = radmesh("solve " + kRoom + " --up z " + daylight + " --cells " + cells +
                                     " --resolution 64 --max-iterations 1 --quiet --stats " + stats);
      EXPECT_EQ(run.exitCode, 0) << run.output;
      return nlohmann::json::parse(std::ifstream(stats))["ledger"];
    };
    const auto sun = ledger("--sun 180,30"), sky = ledger("--sky 10000"), both = ledger("--sun 180,30 --sky 10000");
    const double sunW = sun["emitted"].get<double>(), outside = sun["light_outside"].get<double>();
    ASSERT_LT(outside, 0.99 * sunW) << "the sun does not reach the window: " << sun.dump();
    EXPECT_NEAR(both["light_outside"].get<double>(), outside, 1e-9 * sunW) << cells;
    EXPECT_NEAR(both["emitted"].get<double>(), sunW + sky["emitted"].get<double>(), 1e-9 * sunW) << cells;
  }
}

// A sun along a flat wall sends nothing in: the refusal names the sun and how to turn it (it said
// the scene had no emitter and to add --sun, which was given); one grazing it lights nothing, with a word.
TEST(Cli, ASunThatMissesTheModelIsNamed) {
  const std::string wall = tempPath("wall.mgf");
  std::ofstream(wall) << "m g =\n\trd 0.5\nv a =\n\tp 0 0 0\nv b =\n\tp 4 0 0\nv c =\n\tp 4 0 2\nv d =\n\tp 0 0 2\n"
                         "f a b c d\n";
  CommandRun run = radmesh("solve " + wall + " --up x --sun 0,90 --quiet");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find(wall + ": --sun 0,90,100000: 1 light(s) but no emitter, and they send no light into the model"),
            std::string::npos)
      << run.output;
  run = radmesh("solve " + wall + " --up z --sun 0,90 --quiet");
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("warning: none of the lights' power entered the model"), std::string::npos) << run.output;
}

TEST(Cli, SkyNeedsAnOpeningAndASceneWithoutLightPointsToIt) {
  CommandRun run = radmesh("solve " + kClosedRoom + " --sky 10000 --quiet");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("has no opening to let daylight in"), std::string::npos) << run.output;
  run = radmesh("info " + kRoom);
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--sky LUX"), std::string::npos) << run.output;
  for (const char* bad : {"-5", "nan", "1e308", "1e-40"}) {
    run = radmesh("info " + kRoom + " --sky " + bad);
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("--sky must be the sky's horizontal illuminance in lux, at least 1e-06 and at most 133000"),
              std::string::npos)
        << run.output;
  }
  run = radmesh("info " + kRoom + " --sky 10000 --sky-model clear");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--sky-model must be"), std::string::npos) << run.output;
  // A sky model without a sky would shape nothing, without a word.
  run = radmesh("info " + kRoom + " --sky-model cie-overcast");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--sky-model requires --sky"), std::string::npos) << run.output;
  // Any azimuth is a direction: 1e308 degrees is taken modulo a turn, not refused as a zero scale.
  run = radmesh("info " + kRoom + " --sun 1e308,45 --json");
  EXPECT_EQ(run.exitCode, 0) << run.output;
}

TEST(Cli, WithoutCellTheCellFollowsTheScenesSizeAndCellWins) {
  auto info = [](const std::string& arguments) {
    const CommandRun run = radmesh("info " + arguments + " --json");
    EXPECT_EQ(run.exitCode, 0) << run.output;
    return nlohmann::json::parse(run.output);
  };
  // The 0.55 m Cornell box: a sixteenth of its smallest extent, not the 40 patches of the paper's 15 inches.
  const auto chosen = info("cornell");
  EXPECT_NEAR(chosen["cell_m"].get<double>(), 0.5488 / 16.0, 1e-4) << chosen["cell_why"];
  EXPECT_EQ(chosen["cell"], chosen["cell_m"]);
  EXPECT_NE(chosen["cell_why"].get<std::string>().find("a sixteenth of the model's smallest extent"), std::string::npos);
  EXPECT_GT(chosen["patches"].get<int>(), 1000);
  const auto given = info("cornell --cell 0.381");
  EXPECT_EQ(given["cell_m"], 0.381);
  EXPECT_EQ(given["patches"], 40);
  // A room keeps the paper's 15 inches; solve says what it chose.
  EXPECT_EQ(info("office")["cell_m"], 0.381);
  const CommandRun solve = radmesh("solve cornell --max-iterations 1 --resolution 16 --quiet");
  ASSERT_EQ(solve.exitCode, 0) << solve.output;
  EXPECT_NE(solve.output.find("a sixteenth of the model's smallest extent"), std::string::npos) << solve.output;
}

}  // namespace
}  // namespace radmesh
