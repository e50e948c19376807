// Lights from the command line: --sun alone lights a scene without emitters through its opening,
// on either back end, and impossible values are refused naming the option.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli/cli_run.h"
#include "tests/solver/io/gltf_test_file.h"

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

// info's emitted power holds the sun over the whole model, most of which may never come in: it says
// how much falls outside and how much comes in, the watts a solve's ledger books. The open box (2 m,
// y-up, open to the south) under a sun from the south at 40 degrees takes 3 x 100000 / 179 W/m^2
// over its 4 m^2 opening's 4 cos 40 m^2 shadow; the rest falls on its roof and walls outside.
TEST(CliLights, InfoSaysHowMuchOfTheSunComesInAndHowMuchFallsOutside) {
  const std::string box = test::dataPath("lights/open_box.gltf").string();
  const nlohmann::json info = infoJson(box + " --sun 180,40");
  const double emitted = info["emitted_power"].get<double>(), outside = info["light_outside"].get<double>();
  const double cameIn = 3 * 100000 / 179.0 * 4 * std::cos(40 * std::numbers::pi / 180);  // 5135.5 W
  EXPECT_NEAR(emitted - outside, cameIn, 2e-3 * cameIn);  // pixel centres at the solve's 256x256
  const nlohmann::json solved = solveStats(box + " --sun 180,40 --max-iterations 1", "box.json");
  EXPECT_NEAR(outside, solved["ledger"]["light_outside"].get<double>(), 1e-12 * emitted);
  const CommandRun text = radmesh("info " + box + " --sun 180,40");
  EXPECT_NE(text.output.find(fmt::format("emitted power   {:.6g} W (summed over RGB)\n                of it, {:.6g} W "
                                         "({:.1f}%) is the lights' that falls on the model's outside or past it and "
                                         "never comes in, as a solve books it: {:.6g} W comes in\n",
                                         emitted, outside, 100 * outside / emitted, emitted - outside)),
            std::string::npos)
      << text.output;
  // The Cornell box under a zenith sun takes all of it on its ceiling's back: what comes in is the lamp's.
  const double lamp = infoJson("cornell")["emitted_power"].get<double>();
  const nlohmann::json zenith = infoJson("cornell --sun 0,90");
  EXPECT_NEAR(zenith["emitted_power"].get<double>() - zenith["light_outside"].get<double>(), lamp,
              1e-9 * zenith["emitted_power"].get<double>());
  EXPECT_EQ(infoJson("cornell")["light_outside"], 0.0);
  EXPECT_EQ(radmesh("info cornell").output.find("never comes in"), std::string::npos);
}

// Each cell's ledger, and that they add up to the building's: emitted (the light's power with
// what each cell received of it) = absorbed + unshot + not captured + escaped.
void expectCellsBalance(const nlohmann::json& j) {
  const auto& l = j["ledger"];
  const double emitted = l["emitted"].get<double>();
  EXPECT_LE(l["imbalance"].get<double>(), 1e-9);
  const double accounted = l["absorbed"].get<double>() + l["unshot"].get<double>() + l["not_captured"].get<double>() +
                           l["escaped"].get<double>();
  EXPECT_NEAR(accounted, emitted, 1e-9 * emitted);
  double received = 0.0;
  for (const auto& cell : j["per_cell"]) {
    EXPECT_LE(cell["ledger"]["imbalance"].get<double>(), 1e-9) << cell.dump();
    received += cell["ledger"]["emitted"].get<double>();
  }
  EXPECT_GT(received, 0.0);
  EXPECT_LE(received, emitted * (1 + 1e-12));
}

// The Cornell box under a sun at the zenith: the ceiling's back takes the beam over the box's
// footprint, which is emitted but never comes in. The summary says so under the ledger, with the
// ledger's figure, on both solve paths, and the warning of a solve stopped early says what its
// unshot share is of; without the sun the summary says nothing of it.
TEST(CliLights, TheSunOnTheModelsOutsideIsSaidUnderTheLedger) {
  for (const std::string cells : {"off", "auto"}) {
    const std::string stats = tempPath("outside-" + cells + ".json");
    const CommandRun run = radmesh("solve cornell --sun 0,90 --cell 0.1 --resolution 32 --max-iterations 3 --quiet --cells " +
                                   cells + " --stats " + stats);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const auto l = nlohmann::json::parse(std::ifstream(stats))["ledger"];
    const double outside = l["light_outside"].get<double>(), emitted = l["emitted"].get<double>();
    EXPECT_GT(outside, 0.99 * emitted);  // the lamp inside is under 1.5 W of it
    const size_t at = run.output.find("of it, ");
    ASSERT_NE(at, std::string::npos) << run.output;
    EXPECT_NEAR(std::stod(run.output.substr(at + 7)), outside, 1e-5 * outside) << run.output;
    EXPECT_NE(run.output.find("is the lights' that fell on the model's outside or past it and never came in; the unshot "
                              "fraction is of the "),
              std::string::npos)
        << run.output;
    if (cells == "off") {  // three iterations leave most of it unshot, and the warning says of what
      EXPECT_NE(run.output.find("% of the power that came in unshot"), std::string::npos) << run.output;
    }
  }
  const CommandRun dark = radmesh("solve cornell --cell 0.1 --resolution 32 --max-iterations 3 --quiet");
  ASSERT_EQ(dark.exitCode, 0) << dark.output;
  EXPECT_EQ(dark.output.find("never came in"), std::string::npos) << dark.output;
  EXPECT_NE(dark.output.find("% of the emitted power unshot"), std::string::npos) << dark.output;
}

// --cells auto with lights: a KHR point light in a closed box (one cell), the sun on a building.
TEST(CliLights, CellsAutoSolvesLightsAndTheLedgerBalances) {
  const std::string box = test::dataPath("lights/point_box.gltf").string();
  const nlohmann::json cells =
      solveStats(box + " --cells auto --cell 0.25 --resolution 32 --until-unshot 0.02 --quiet", "cells.json");
  const nlohmann::json whole = solveStats(box + " --cell 0.25 --resolution 32 --until-unshot 0.02 --quiet", "whole.json");
  EXPECT_EQ(cells["cells"], 1);
  expectCellsBalance(cells);
  // 179 cd white: 1 W/sr per channel, 4 pi W each, all of it landing inside the closed box.
  EXPECT_NEAR(cells["ledger"]["emitted"].get<double>(), 3 * 4 * 3.141592653589793, 1e-9);
  EXPECT_NEAR(cells["per_cell"][0]["ledger"]["emitted"].get<double>(), cells["ledger"]["emitted"].get<double>(), 1e-9);
  EXPECT_NEAR(cells["ledger"]["absorbed"].get<double>(), whole["ledger"]["absorbed"].get<double>(),
              0.02 * whole["ledger"]["emitted"].get<double>());

  const nlohmann::json sun = solveStats(
      "building:2x1 --sun 135,40 --cells auto --cell 0.75 --resolution 16 --until-unshot 0.05 --quiet", "sun.json");
  expectCellsBalance(sun);
  EXPECT_LE(sun["unshot_fraction"].get<double>(), 0.05);
  EXPECT_GT(sun["ledger"]["light_outside"].get<double>(), 0.0);  // the sun on the roof and past the building
}

// The i-th of many point lights spread over the inside of the room below, 0.3 m or more from its walls.
Vec3 spreadLight(int i) {
  const auto fraction = [i](double step) { return i * step - std::floor(i * step); };
  return {0.3 + 5.4 * fraction(0.6180339887), 0.3 + 2.4 * fraction(0.7548776662), 0.3 + 3.4 * fraction(0.5698402910)};
}

// A 6 x 3 x 4 m room (glTF, y up), one-sided grey walls facing in, with a 1 x 1 m window in its
// x = 6 wall, lit by `count` point lights of 10 cd (spreadLight); written to `path`.
std::string roomWithPointLights(const std::string& path, int count) {
  test::GltfBuilder b;
  std::vector<Vec3> corners;
  std::vector<uint32_t> indices;
  // A rectangle from `a` along `u` and `v`, turned to face `inward`.
  const auto quad = [&](Vec3 a, Vec3 u, Vec3 v, Vec3 inward) {
    if (glm::dot(glm::cross(u, v), inward) < 0.0) std::swap(u, v);
    const auto first = static_cast<uint32_t>(corners.size());
    corners.insert(corners.end(), {a, a + u, a + u + v, a + v});
    indices.insert(indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
  };
  const Vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  quad({0, 0, 0}, 6.0 * x, 4.0 * z, y);          // floor
  quad({0, 3, 0}, 6.0 * x, 4.0 * z, -y);         // ceiling
  quad({0, 0, 0}, 6.0 * x, 3.0 * y, z);          // z = 0
  quad({0, 0, 4}, 6.0 * x, 3.0 * y, -z);         // z = 4
  quad({0, 0, 0}, 4.0 * z, 3.0 * y, x);          // x = 0
  quad({6, 0, 0}, 1.5 * z, 3.0 * y, -x);         // x = 6 around the window: z in [1.5, 2.5], y in [1, 2]
  quad({6, 0, 2.5}, 1.5 * z, 3.0 * y, -x);
  quad({6, 0, 1.5}, 1.0 * z, 1.0 * y, -x);
  quad({6, 2, 1.5}, 1.0 * z, 1.0 * y, -x);
  const int grey = b.add("materials", {{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.5, 0.5, 1}}, {"metallicFactor", 0}}}});
  b.addTriangles("room", b.addPositions(corners), b.addIndices(indices), grey);
  b.doc()["extensionsUsed"] = {"KHR_lights_punctual"};
  b.doc()["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"intensity", 10}}};
  for (int i = 0; i < count; ++i) {
    const Vec3 p = spreadLight(i);
    b.add("nodes", {{"translation", {p.x, p.y, p.z}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  }
  return b.write(path).string();
}

// The solid angle of the rectangle [u0, u1] x [v0, v1] in a plane at distance d, seen from the point
// over its origin.
double rectangleSolidAngle(double d, double u0, double u1, double v0, double v1) {
  const auto corner = [d](double u, double v) { return std::atan(u * v / (d * std::sqrt(d * d + u * u + v * v))); };
  return corner(u1, v1) - corner(u0, v1) - corner(u1, v0) + corner(u0, v0);
}

// What info says many point lights send out of a room is what goes through its window (each
// light's solid angle of it over 4 pi), as a solve books it: their rows share one projection.
TEST(CliLights, InfoSaysWhatManyPointLightsSendOutOfTheWindow) {
  constexpr int kLights = 30;
  const std::string room = roomWithPointLights(tempPath("room.gltf"), kLights);
  const nlohmann::json info = infoJson(room);
  ASSERT_EQ(info["lights"], kLights);
  double through = 0.0;  // of the emitted power
  for (int i = 0; i < kLights; ++i) {
    const Vec3 p = spreadLight(i);
    through += rectangleSolidAngle(6.0 - p.x, 1.5 - p.z, 2.5 - p.z, 1.0 - p.y, 2.0 - p.y) / (4 * std::numbers::pi);
  }
  through /= kLights;
  const double emitted = info["emitted_power"].get<double>(), outside = info["light_outside"].get<double>();
  EXPECT_NEAR(emitted, kLights * 3 * 4 * std::numbers::pi * 10 / 179.0, 1e-9 * emitted);
  EXPECT_NEAR(outside / emitted, through, 0.01 * through);  // pixel centres at 256 x 256 a cube face
  const nlohmann::json solved = solveStats(room + " --max-iterations 1", "room.json");
  EXPECT_NEAR(outside, solved["ledger"]["light_outside"].get<double>(), 1e-12 * emitted);
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
