// --units: a model drawn in millimetres (or cm, in, ft) loads as the same model in metres, and one
// that would be over a kilometre across in metres is noted.
#include "solver/scene/units.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>

#include "solver/io/scene_loader.h"
#include "solver/scene/scene_error.h"

namespace radmesh {
namespace {

// A 4 x 3 x 2.5 m room lit by a 1 m square under its ceiling, written in units of 1/scale metres.
std::string unitsRoomMgf(double scale) {
  const double w = 4 * scale, d = 3 * scale, h = 2.5 * scale, l = 2.49 * scale;
  const std::vector<std::array<double, 3>> points = {
      {0, 0, 0}, {w, 0, 0}, {w, d, 0}, {0, d, 0}, {0, 0, h}, {w, 0, h}, {w, d, h}, {0, d, h},
      {1.5 * scale, 1 * scale, l}, {1.5 * scale, 2 * scale, l}, {2.5 * scale, 2 * scale, l}, {2.5 * scale, 1 * scale, l}};
  std::string mgf = "m white =\n c\n rd 0.5\nm lamp =\n c\n ed 179\n";
  for (size_t k = 0; k < points.size(); ++k)
    mgf += "v p" + std::to_string(k) + " =\n p " + std::to_string(points[k][0]) + " " + std::to_string(points[k][1]) +
           " " + std::to_string(points[k][2]) + "\n";
  // Floor, ceiling and four walls facing in; the lamp facing down.
  mgf += "m white\nf p0 p1 p2 p3\nf p4 p7 p6 p5\nf p0 p3 p7 p4\nf p1 p5 p6 p2\nf p0 p4 p5 p1\nf p3 p2 p6 p7\n";
  mgf += "m lamp\nf p8 p9 p10 p11\n";
  return mgf;
}

std::string writeUnitsRoom(double scale, const std::string& name) {
  const auto path = std::filesystem::temp_directory_path() / ("radmesh-units-" + std::to_string(getpid()) + "-" + name);
  std::ofstream(path) << unitsRoomMgf(scale);
  return path.string();
}

TEST(Units, ParsesTheFiveUnitsAndRefusesAnythingElse) {
  EXPECT_EQ(parseUnits("m"), 1.0);
  EXPECT_EQ(parseUnits("cm"), 0.01);
  EXPECT_EQ(parseUnits("mm"), 0.001);
  EXPECT_EQ(parseUnits("in"), 0.0254);
  EXPECT_EQ(parseUnits("ft"), 0.3048);
  for (const char* bad : {"M", "km", "", "0.001"}) {
    try {
      parseUnits(bad);
      ADD_FAILURE() << "'" << bad << "' accepted";
    } catch (const OptionError& e) {
      EXPECT_EQ(std::string(e.what()), std::string("--units '") + bad +
                                           "' is not a unit: give m, cm, mm, in or ft (what the file's coordinates are in)");
    }
  }
}

TEST(Units, ARoomInMillimetresLoadsAsTheSameRoomInMetres) {
  const std::string metres = writeUnitsRoom(1.0, "m.mgf"), millimetres = writeUnitsRoom(1000.0, "mm.mgf");
  // The notes on how each file is read: with the axis given, only the units'.
  std::vector<std::string> metreNotes, scaledNotes, unscaledNotes, daylightNotes;
  const Scene reference = loadScene(metres, nullptr, {}, &daylightNotes, UpChoice::Z, &metreNotes);
  const Scene scaled = loadScene(millimetres, nullptr, {}, &daylightNotes, UpChoice::Z, &scaledNotes, parseUnits("mm"));
  const Scene unscaled = loadScene(millimetres, nullptr, {}, &daylightNotes, UpChoice::Z, &unscaledNotes);
  ASSERT_EQ(scaled.polygons.size(), reference.polygons.size());
  for (size_t p = 0; p < scaled.polygons.size(); ++p)
    for (size_t v = 0; v < scaled.polygons[p].vertices.size(); ++v)
      for (int axis = 0; axis < 3; ++axis)
        EXPECT_NEAR(scaled.polygons[p].vertices[v][axis], reference.polygons[p].vertices[v][axis], 1e-12);
  // ed is per square metre: the lamp's 1 m^2 gives 3 W, however the file is drawn.
  EXPECT_NEAR(emittedPowerW(reference), 3.0, 1e-12);
  EXPECT_NEAR(emittedPowerW(scaled), 3.0, 1e-9);
  EXPECT_NEAR(emittedPowerW(unscaled), 3.0e6, 1e-3);
  EXPECT_TRUE(daylightNotes.empty());  // not a daylight line (info --json lists those under "daylight")
  EXPECT_TRUE(metreNotes.empty());
  EXPECT_TRUE(scaledNotes.empty());
  ASSERT_EQ(unscaledNotes.size(), 1u);
  EXPECT_EQ(unscaledNotes[0],
            "the model is 4000 m across, read in metres; if its coordinates are in millimetres, centimetres, inches or "
            "feet, give --units mm, cm, in or ft (the cell, the eye height and the walking pace are in metres)");
  std::filesystem::remove(metres);
  std::filesystem::remove(millimetres);
}

// A room drawn in metres read as millimetres is 4 mm across, one drawn in units of 1e-5 m read as
// metres 400 km: each a warning naming the file, the size and the unit that gives a room's size; the room
// read in the unit it is drawn in is not warned of.
TEST(Units, AModelScaledToNoBuildingsSizeIsWarnedOfWithTheFix) {
  const std::string metres = writeUnitsRoom(1.0, "small.mgf"), large = writeUnitsRoom(1e5, "large.mgf");
  const auto warningsOf = [](const std::string& path, const char* units) {
    std::vector<std::string> warnings;
    loadScene(path, &warnings, {}, nullptr, UpChoice::Z, nullptr, parseUnits(units));
    return warnings;
  };
  EXPECT_EQ(warningsOf(metres, "mm"),
            std::vector<std::string>{metres + ": with --units mm the model is 0.004 m across, too small for a building, "
                                              "a room or a luminaire (under 0.05 m): if its coordinates are metres, "
                                              "leave --units out (it is then 4 m across)"});
  EXPECT_EQ(warningsOf(large, "m"),
            std::vector<std::string>{large + ": with --units m the model is 400000 m across, too large for a building, a "
                                            "room or a luminaire (over 100000 m): if its coordinates are in mm, give "
                                            "--units mm (it is then 400 m across)"});
  EXPECT_TRUE(warningsOf(metres, "m").empty());
  EXPECT_TRUE(warningsOf(metres, "ft").empty());  // 1.2 m: a luminaire's size
  EXPECT_TRUE(warningsOf(large, "mm").empty());
  std::filesystem::remove(metres);
  std::filesystem::remove(large);
}

TEST(Units, LightsMoveWithTheModelAndKeepTheirIntensity) {
  Scene scene;
  scene.polygons.push_back({{{0, 0, 0}, {1000, 0, 0}, {1000, 1000, 0}}, 0, "f"});
  Light lamp;
  lamp.position = {500, 250, 2000};
  lamp.intensity = Rgb(2.0);
  scene.lights.push_back(lamp);
  scaleScene(scene, 0.001);
  EXPECT_EQ(scene.polygons[0].vertices[2], Vec3(1.0, 1.0, 0.0));
  EXPECT_EQ(scene.lights[0].position, Vec3(0.5, 0.25, 2.0));
  EXPECT_EQ(scene.lights[0].intensity, Rgb(2.0));  // W/sr: the irradiance it gives follows the distances
  EXPECT_EQ(unitsNote(scene), "");
}

}  // namespace
}  // namespace radmesh
