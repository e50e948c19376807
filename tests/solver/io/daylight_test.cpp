// Daylight: openings found from geometry, the sky models' closed forms against quadrature, and the
// sky's emitters in a room with one window.
#include "solver/io/daylight.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "solver/geometry/openings.h"
#include "solver/io/builtin_scenes.h"
#include "solver/io/mgf_color.h"
#include "solver/io/mgf_import.h"
#include "solver/io/scene_loader.h"
#include "solver/scene/scene_error.h"
#include "tests/test_paths.h"

namespace radmesh {
namespace {

const std::string kRoom = test::dataPath("daylight/room_one_window.mgf").string();
const std::string kClosedRoom = test::dataPath("daylight/room_closed.mgf").string();
constexpr double kWindowM2 = 1.2 * 1.2;

// The sky's illuminance on a plane of normal n, summed over a fine grid of directions: zenith
// angle and azimuth midpoints, L(theta) sin(theta) cos(incidence).
double quadratureLux(SkyModel model, double horizontalLux, const Vec3& n) {
  const int rows = 400, columns = 800;
  const double lz = model == SkyModel::Uniform ? horizontalLux / std::numbers::pi : 9.0 * horizontalLux / (7.0 * std::numbers::pi);
  double sum = 0.0;
  for (int i = 0; i < rows; ++i) {
    const double theta = (i + 0.5) * (std::numbers::pi / 2) / rows;
    const double luminance = model == SkyModel::Uniform ? lz : lz * (1.0 + 2.0 * std::cos(theta)) / 3.0;
    for (int j = 0; j < columns; ++j) {
      const double phi = (j + 0.5) * 2.0 * std::numbers::pi / columns;
      const Vec3 w(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      sum += luminance * std::max(0.0, glm::dot(w, n)) * std::sin(theta);
    }
  }
  return sum * (std::numbers::pi / 2 / rows) * (2.0 * std::numbers::pi / columns);
}

TEST(Daylight, SkyClosedFormsMatchQuadratureAtEveryTilt) {
  for (SkyModel model : {SkyModel::Uniform, SkyModel::CieOvercast}) {
    EXPECT_NEAR(skyIlluminanceLux(model, 10000.0, 1.0), 10000.0, 1e-9) << toString(model);
    EXPECT_EQ(skyIlluminanceLux(model, 10000.0, -1.0), 0.0) << toString(model);
    for (double degrees : {0.0, 30.0, 60.0, 90.0, 120.0, 150.0}) {
      const double tilt = degrees * std::numbers::pi / 180.0;
      const Vec3 n(std::sin(tilt), 0.0, std::cos(tilt));
      // The midpoint rule's error on this grid is below 1e-5 of the horizontal illuminance.
      EXPECT_NEAR(skyIlluminanceLux(model, 10000.0, std::cos(tilt)), quadratureLux(model, 10000.0, n), 0.1)
          << toString(model) << " at " << degrees << " degrees";
    }
  }
  // A vertical window: half of a uniform sky; 0.396 of an overcast one (the zenith is brighter).
  EXPECT_NEAR(skyIlluminanceLux(SkyModel::Uniform, 1.0, 0.0), 0.5, 1e-15);
  EXPECT_NEAR(skyIlluminanceLux(SkyModel::CieOvercast, 1.0, 0.0), 9.0 / (7.0 * std::numbers::pi) * (std::numbers::pi / 6.0 + 4.0 / 9.0), 1e-15);
  EXPECT_NEAR(skyIlluminanceLux(SkyModel::CieOvercast, 1.0, 0.0), 0.3962, 1e-4);
}

TEST(Daylight, TheRoomHasExactlyOneOpeningTheWindowFacingIn) {
  const Scene room = importMgf(kRoom);
  const OpeningSearch search = findOpenings(room);
  ASSERT_EQ(search.openings.size(), 1u);
  EXPECT_EQ(search.skipped.lines(), std::vector<std::string>{});
  const OpeningPolygon& window = search.openings[0];
  EXPECT_EQ(window.vertices.size(), 4u);  // the wall pieces' collinear edges merged
  EXPECT_NEAR(polygonArea(window.vertices), kWindowM2, 1e-9);
  const Vec3 n = glm::normalize(newellNormal(window.vertices));
  EXPECT_NEAR(n.y, 1.0, 1e-12);  // into the room, as the wall around it faces
  for (const Vec3& v : window.vertices) EXPECT_NEAR(v.y, 0.0, 1e-12);
  EXPECT_NEAR(window.inside.y, 0.0, 1e-12);
  EXPECT_TRUE(findOpenings(importMgf(kClosedRoom)).openings.empty());
}

TEST(Daylight, TheWindowEmitsWhatTheSkyGivesAVerticalWindow) {
  for (SkyModel model : {SkyModel::Uniform, SkyModel::CieOvercast}) {
    std::vector<std::string> notes;
    const Scene room = loadScene(kRoom, nullptr, Daylight{10000.0, model}, &notes);
    const double lux = model == SkyModel::Uniform ? 5000.0 : 10000.0 * 9.0 / (7.0 * std::numbers::pi) * (std::numbers::pi / 6.0 + 4.0 / 9.0);
    // Summed over R, G, B, at MGF's white 179 lm/W.
    const double expectedW = 3.0 * kWindowM2 * lux / kWhiteEfficacyLmPerW;
    EXPECT_NEAR(emittedPowerW(room), expectedW, 1e-12 * expectedW) << toString(model);
    const Material& sky = room.materials.back();
    EXPECT_EQ(sky.name, "sky (opening 1)");
    EXPECT_EQ(sky.rho, Rgb(0.0));
    EXPECT_EQ(room.polygons.back().material, static_cast<int>(room.materials.size() - 1));
    ASSERT_FALSE(notes.empty());
    EXPECT_NE(notes[0].find("through 1 opening(s), 1.44 m^2"), std::string::npos) << notes[0];
  }
}

TEST(Daylight, WithoutAnOpeningOrAnEmitterTheErrorsSayHowToLightIt) {
  try {
    loadScene(kClosedRoom, nullptr, Daylight{10000.0});
    FAIL() << "a closed room has no opening to let the sky in";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("no opening to let daylight in"), std::string::npos) << e.what();
  }
  try {
    loadScene(kRoom);
    FAIL() << "the room has no light of its own";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("--sky LUX"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--sun"), std::string::npos) << e.what();
  }
}

// A unit box of inward faces without its lid, or of outward faces without its floor.
Scene openBox(bool inward) {
  Scene s;
  s.source = inward ? "open-top room" : "shell on no floor";
  s.materials.push_back({"grey", Rgb(0.5), Rgb(0.0)});
  const Vec3 c[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int outward[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  for (int f = 0; f < 6; ++f) {
    if (f == (inward ? 1 : 0)) continue;  // the lid of the room, the floor of the shell
    Polygon p;
    for (int k = 0; k < 4; ++k) p.vertices.push_back(c[outward[f][inward ? 3 - k : k]]);
    s.polygons.push_back(p);
  }
  return s;
}

TEST(Daylight, AnOpenTopSeesTheWholeSkyAndTheRimOfAShellNone) {
  Scene room = openBox(true);
  addSkyEmitters(room, Daylight{1000.0, SkyModel::CieOvercast});
  EXPECT_NEAR(emittedPowerW(room), 3.0 * 1000.0 / kWhiteEfficacyLmPerW, 1e-12);
  EXPECT_NEAR(glm::normalize(newellNormal(room.polygons.back().vertices)).z, -1.0, 1e-12);  // shining down, in
  // The rim of a shell standing on no floor looks up into its own roof: not a way in for the sky.
  Scene shell = openBox(false);
  try {
    addSkyEmitters(shell, Daylight{1000.0});
    FAIL() << "the shell's rim is no opening";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("looks out onto the model itself"), std::string::npos) << e.what();
  }
}

// The office is closed: its furniture's shells, open at the bottom, stand on the floor, which
// closes them, so it has no loop at all. Lifted 1 cm off the floor they leave 53 loops, none an
// opening. The refusal tells each kind of loop once, not all of them (it used to run to 30,000
// characters).
TEST(Daylight, AClosedRoomsRefusalCountsItsLoopsByKind) {
  Scene office = builtinScene("office");
  EXPECT_TRUE(findOpenings(office).skipped.lines().empty());
  for (Polygon& p : office.polygons)
    if (p.origin.rfind("room ", 0) != 0)
      for (Vec3& v : p.vertices) v.z += 0.01;
  try {
    addSkyEmitters(office, Daylight{1000.0});
    FAIL() << "the office has no opening";
  } catch (const SceneError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("does not close: it is not an opening (and 5 more like it)"), std::string::npos) << what;
    EXPECT_NE(what.find("not the sky: no daylight there (and 46 more like it)"), std::string::npos) << what;
    EXPECT_LT(what.size(), 800u) << what;
  }
}

TEST(Daylight, BoundarySegmentsSeeThroughTJunctions) {
  const Scene room = importMgf(kRoom);
  double length = 0.0;
  for (const BoundarySegment& s : boundarySegments(room, 1e-9)) length += glm::length(s.b - s.a);
  EXPECT_NEAR(length, 4 * 1.2, 1e-12);  // the window's rim, nothing else
  EXPECT_TRUE(boundarySegments(importMgf(kClosedRoom), 1e-9).empty());
}

}  // namespace
}  // namespace radmesh
