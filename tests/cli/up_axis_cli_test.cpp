// --up on the commands, and bakes: written y-up, described by `info` and walked by the viewer
// with no solve.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli/cli_run.h"
#include "viewer/image.h"

namespace radmesh {
namespace {

const std::string kYUpRoom = test::dataPath("yup_room.gltf").string();

TEST(UpAxisCli, InfoGivesTheUpAxisTheFormatOrTheOptionSets) {
  EXPECT_EQ(infoJson(kYUpRoom)["up"], "y");
  EXPECT_EQ(infoJson(kYUpRoom)["kind"], "scene");
  EXPECT_EQ(infoJson("office")["up"], "z");
  EXPECT_EQ(infoJson("office --up x")["up"], "x");
  const CommandRun text = radmesh("info " + kYUpRoom);
  ASSERT_EQ(text.exitCode, 0) << text.output;
  EXPECT_NE(text.output.find("\nup              y\n"), std::string::npos) << text.output;
}

TEST(UpAxisCli, AutoSaysWhatItChoseOnOneLine) {
  const CommandRun run = radmesh("info " + kYUpRoom + " --up auto");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("radmesh: --up auto: y is up (the axis along which the floor faces up at the bottom and "
                            "the lights face down)\n"),
            std::string::npos)
      << run.output;
  EXPECT_EQ(infoJson("office --up auto")["up"], "z");
}

TEST(UpAxisCli, ABadUpIsRefusedOnEveryCommand) {
  for (const std::string command : {"info office", "solve office --max-iterations 1", "bench solve cornell"}) {
    const CommandRun run = radmesh(command + " --up w");
    EXPECT_NE(run.exitCode, 0) << command;
    EXPECT_NE(run.output.find("--up 'w' is not an axis: give x, y, z, or auto"), std::string::npos)
        << command << ": " << run.output;
  }
}

// --units scales what the file holds to metres: the built-in office read as millimetres is a
// thousandth of its size, a millionth of its area and power (emittance stays per square metre).
TEST(UpAxisCli, UnitsScaleTheSceneOnEveryCommandAndABadOneIsRefused) {
  const nlohmann::json metres = infoJson("office");
  const nlohmann::json millimetres = infoJson("office --units mm");
  EXPECT_NEAR(millimetres["total_area"].get<double>(), 1e-6 * metres["total_area"].get<double>(),
              1e-12 * metres["total_area"].get<double>());
  EXPECT_NEAR(millimetres["emitted_power"].get<double>(), 1e-6 * metres["emitted_power"].get<double>(),
              1e-12 * metres["emitted_power"].get<double>());
  EXPECT_EQ(metres["metres_per_unit"], 1.0);
  EXPECT_EQ(millimetres["metres_per_unit"], 0.001);
  EXPECT_NEAR(infoJson("office --units ft")["bounds_max"][2].get<double>(),
              0.3048 * metres["bounds_max"][2].get<double>(), 1e-12);
  for (const std::string command : {"info office", "solve office --max-iterations 1", "render office",
                                    "bench solve cornell", "bench accuracy cornell"}) {
    const CommandRun run = radmesh(command + " --units furlong");
    EXPECT_EQ(run.exitCode, 2) << command;
    EXPECT_NE(run.output.find("--units 'furlong' is not a unit: give m, cm, mm, in or ft"), std::string::npos)
        << command << ": " << run.output;
  }
}

// --units that make a model no building, room or luminaire (the office, 7.35 m in metres, read as
// millimetres) is a counted warning naming the file, the size and the fix, refused under --strict in
// the same words;
// the shared scenes that are small, read as they are drawn, are not warned of.
TEST(UpAxisCli, UnitsThatMakeTheModelImplausiblySizedAreWarnedOf) {
  const std::string warning = "office: with --units mm the model is 0.00735 m across, too small for a building, a "
                              "room or a luminaire (under 0.05 m): if its coordinates are metres, leave --units out "
                              "(it is then 7.35 m across)";
  const CommandRun run = radmesh("info office --units mm");
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("radmesh: warning: " + warning + "\n"), std::string::npos) << run.output;
  EXPECT_EQ(infoJson("office --units mm")["warnings"], nlohmann::json::array({warning}));
  const CommandRun strict = radmesh("info office --units mm --strict");
  EXPECT_EQ(strict.exitCode, 2) << strict.output;
  // The refusal says what was wrong and the fix in plain words, the file named once.
  EXPECT_EQ(strict.output, "radmesh: error: office: refused under --strict (each warning an error): " +
                               warning.substr(std::string("office: ").size()) +
                               " (fix: correct what the warning names, or leave --strict out to open it as warned)\n");
  EXPECT_EQ(infoJson("office --units ft")["warnings"], nlohmann::json::array());  // 2.24 m across
  RADMESH_REQUIRE_SHARED(luminaire, "scenes/mgf/examp1.mgf");
  RADMESH_REQUIRE_SHARED(cube, "scenes/mgf/cube.mgf");
  const auto warnedOfUnits = [](const std::string& arguments) {  // their other warnings are the MGF's own
    const nlohmann::json warnings = infoJson(arguments)["warnings"];
    return std::ranges::any_of(warnings, [](const nlohmann::json& w) {
      return w.get<std::string>().find("--units") != std::string::npos;
    });
  };
  for (const char* units : {"", " --units m"}) EXPECT_FALSE(warnedOfUnits(luminaire.string() + units)) << units;
  for (const char* units : {"", " --units m", " --units cm"})  // 10 units: 0.1 m in cm
    EXPECT_FALSE(warnedOfUnits(cube.string() + units)) << units;
  EXPECT_TRUE(warnedOfUnits(luminaire.string() + " --units mm"));  // 1.2 mm
}

#ifdef RADMESH_HAS_VIEWER
// A room read in millimetres, 2.7 mm tall, is drawn lit: the walk's near plane (5 mm at the least)
// lay past its far wall and the picture was black.
TEST(UpAxisCli, ARoomReadInMillimetresIsDrawn) {
  const std::string png = tempPath("mm.png");
  const CommandRun run = radmesh("render " + test::dataPath("daylight/room_one_window.mgf").string() +
                                 " --units mm --sky 10000 --iterations 5 --size 160x120 --quiet --out " + png);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(run.output.find("shows nothing of the model"), std::string::npos) << run.output;
  const Image picture = readPng(png);
  int lit = 0;
  for (size_t i = 0; i < picture.rgba.size(); i += 4)
    lit += picture.rgba[i] + picture.rgba[i + 1] + picture.rgba[i + 2] > 0;
  EXPECT_EQ(lit, 160 * 120) << png;
}
#endif

// A model read in metres that is 2 km across is noted, as the axis MGF does not give is: on stderr,
// one line each, so `info --json` stays JSON and its "daylight" lines are daylight's.
TEST(UpAxisCli, AModelOverAKilometreIsNotedBesideTheJsonNotInIt) {
  const std::string path = tempPath("plaza.mgf");
  std::ofstream(path) << "m lamp =\n\tc\n\ted 10\n"
                         "v a =\n\tp 0 0 0\nv b =\n\tp 2000 0 0\nv c =\n\tp 2000 2000 0\nv d =\n\tp 0 2000 0\n"
                         "f a b c d\n";
  const CommandRun run = radmesh("info " + path + " --cell 100 --json");  // a coarse cell: meshed at once
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("radmesh: the model is 2000 m across, read in metres; if its coordinates are in "
                            "millimetres"),
            std::string::npos)
      << run.output;
  const nlohmann::json j = jsonOf(run);
  EXPECT_EQ(j["daylight"], nlohmann::json::array());
  EXPECT_EQ(j["metres_per_unit"], 1.0);
  EXPECT_EQ(radmesh("info " + path + " --cell 100 --units mm").output.find("the model is"), std::string::npos);
}

// A 4 x 3 m room (a floor and four walls), as drawn, or turned by `turn` degrees about z.
std::string roomMgf(const std::string& name, const std::string& turn) {
  const std::string path = tempPath(name);
  std::ofstream out(path);
  out << "m white =\n\tc\n\trd 0.5\n\ted 1\n";  // every surface glows: info needs an emitter
  if (!turn.empty()) out << "xf -rz " << turn << "\n";
  const char* corners[] = {"0 0", "4 0", "4 3", "0 3"};
  for (int i = 0; i < 4; ++i)
    out << "v f" << i << " =\n\tp " << corners[i] << " 0\nv c" << i << " =\n\tp " << corners[i] << " 2.5\n";
  out << "f f0 f1 f2 f3\n";
  for (int i = 0; i < 4; ++i) out << "f f" << i << " c" << i << " c" << (i + 1) % 4 << " f" << (i + 1) % 4 << "\n";
  if (!turn.empty()) out << "xf\n";
  return path;
}

TEST(UpAxisCli, AModelAtAnAngleToTheAxesIsMeshedOnAGridTurnedWithIt) {
  const nlohmann::json along = infoJson(roomMgf("room.mgf", "") + " --cell 0.381");
  const nlohmann::json turned = infoJson(roomMgf("room30.mgf", "30") + " --cell 0.381");
  EXPECT_EQ(along["grid_turn_degrees"], 0.0);
  EXPECT_NEAR(turned["grid_turn_degrees"].get<double>(), 30.0, 1e-9);
  EXPECT_EQ(along["grid_turns"].size(), 0u);
  ASSERT_EQ(turned["grid_turns"].size(), 1u);
  EXPECT_EQ(turned["grid_turns"][0]["axis"], "z");
  EXPECT_EQ(turned["grid_turns"][0]["polygons"], 5);  // the floor and the four walls
  // 11 x 8 floor cells, the same turned: the world grid cut it into slivers along the walls.
  EXPECT_EQ(along["patches"], turned["patches"]);
  const CommandRun text = radmesh("info " + roomMgf("room30.mgf", "30") + " --cell 0.381");
  EXPECT_NE(text.output.find("\ngrid            turned 30 degrees about z for all 5 polygons\n"), std::string::npos)
      << text.output;
  // The office is along the axes but for its round table, whose facets each get a grid of their own.
  const CommandRun office = radmesh("info office");
  EXPECT_EQ(office.output.find("\ngrid            turned"), std::string::npos) << office.output;
  EXPECT_NE(office.output.find("\ngrid            its own for 35 polygons, each at an angle to the model's grids\n"), std::string::npos)
      << office.output;
  EXPECT_EQ(infoJson("office")["own_grid_polygons"], 35);
  EXPECT_EQ(along["own_grid_polygons"], 0);
}

TEST(UpAxisCli, TheOfficesBakeIsYUpAndInfoDescribesItAsABake) {
  const std::string bake = tempPath("office.glb");
  const CommandRun solve = radmesh("solve office --cell 1 --resolution 32 --max-iterations 5 --quiet --out " + bake);
  ASSERT_EQ(solve.exitCode, 0) << solve.output;
  const nlohmann::json scene = infoJson("office --cell 1");
  const nlohmann::json j = infoJson(bake);
  EXPECT_EQ(j["kind"], "bake");
  EXPECT_EQ(j["made_by"], "radmesh");
  EXPECT_EQ(j["up"], "y");
  EXPECT_EQ(j["source_up"], "z");
  EXPECT_GT(j["triangles"].get<int>(), 0);
  EXPECT_TRUE(j["warnings"].empty());
  // (x, y, z) -> (x, z, -y): the office's 2.7 m height is along glTF's y, its 5.4 m depth along -z.
  for (int c = 0; c < 3; ++c) {
    const int from = c == 0 ? 0 : c == 1 ? 2 : 1;
    const double sign = c == 2 ? -1.0 : 1.0;
    EXPECT_NEAR(j["bounds_min"][c].get<double>(), sign * scene[c == 2 ? "bounds_max" : "bounds_min"][from].get<double>(), 1e-6);
    EXPECT_NEAR(j["bounds_max"][c].get<double>(), sign * scene[c == 2 ? "bounds_min" : "bounds_max"][from].get<double>(), 1e-6);
  }
  EXPECT_NEAR(j["bounds_max"][1].get<double>() - j["bounds_min"][1].get<double>(), 2.7, 1e-6);
  EXPECT_NEAR(j["total_area"].get<double>(), scene["total_area"].get<double>(), 1e-5 * scene["total_area"].get<double>());

  const CommandRun text = radmesh("info " + bake);
  ASSERT_EQ(text.exitCode, 0) << text.output;
  EXPECT_NE(text.output.find("bake            " + bake + " (by radmesh;"), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("up              y (the scene's z turned onto glTF's y)"), std::string::npos) << text.output;
  EXPECT_EQ(text.output.find("emitter"), std::string::npos) << text.output;
  // The scene's flags shape nothing of a bake's figures: each is named, not dropped without a word.
  const CommandRun flags = radmesh("info " + bake + " --cell 0.5 --min-element 0.1 --cells --up y");
  ASSERT_EQ(flags.exitCode, 0) << flags.output;
  for (const char* flag : {"--cell", "--min-element", "--cells"})
    EXPECT_NE(flags.output.find(fmt::format("warning: {} does not apply: {} is a bake", flag, bake)), std::string::npos)
        << flags.output;
  EXPECT_EQ(flags.output.find("--up does not apply"), std::string::npos) << flags.output;

  const CommandRun again = radmesh("solve " + bake);
  EXPECT_EQ(again.exitCode, 2) << again.output;
  EXPECT_NE(again.output.find("is a bake, already solved: there is nothing to solve"), std::string::npos)
      << again.output;
}

TEST(UpAxisCli, TheViewerWalksABakeWithNoSolve) {
  const std::string viewer = (test::binaryDir() / "viewer" / "radmesh-view").string();
  if (!std::filesystem::exists(viewer)) GTEST_SKIP() << "radmesh-view is not built";
  if (std::system("command -v xvfb-run > /dev/null") != 0) GTEST_SKIP() << "xvfb-run is not installed";
  const std::string bake = tempPath("two-rooms.glb"), png = tempPath("walk.png");
  ASSERT_EQ(radmesh("solve two-rooms --cell 1 --resolution 32 --max-iterations 5 --quiet --out " + bake).exitCode, 0);
  const CommandRun run = runCommand(virtualDisplay("800x600x24") + viewer + " " + bake +
                                     " --cell 0.5 --up y --size 800x600 --steps 1 --screenshot " + png);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("warning: --cell does not apply: " + bake + " is a bake"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("--up does not apply"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("scene does not apply"), std::string::npos) << run.output;  // the bake itself is no flag
  EXPECT_NE(run.output.find("wrote " + png), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("a bake, nothing to solve"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("no emitter"), std::string::npos) << run.output;
  EXPECT_EQ(pngSize(png), std::make_pair(800, 600));
}

}  // namespace
}  // namespace radmesh
