// The up axis: the format's convention by default, --up to say otherwise, and --up auto's rule on
// the scenes radmesh ships and the shared ones.
#include "solver/scene/up_axis.h"

#include <gtest/gtest.h>

#include <cmath>

#include "solver/io/scene_loader.h"
#include "solver/scene/scene_error.h"
#include "solver/scene/sun.h"
#include "tests/test_paths.h"

namespace radmesh {
namespace {

TEST(UpAxis, ParsesTheAxesAndAutoAndRefusesAnythingElse) {
  EXPECT_EQ(parseUpChoice("x"), UpChoice::X);
  EXPECT_EQ(parseUpChoice("y"), UpChoice::Y);
  EXPECT_EQ(parseUpChoice("z"), UpChoice::Z);
  EXPECT_EQ(parseUpChoice("auto"), UpChoice::Auto);
  for (const char* bad : {"Y", "w", "", "-z"}) {
    try {
      parseUpChoice(bad);
      ADD_FAILURE() << "'" << bad << "' accepted";
    } catch (const OptionError& e) {
      EXPECT_EQ(std::string(e.what()), std::string("--up '") + bad +
                                           "' is not an axis: give x, y, z, or auto (decided from the geometry)");
    }
  }
}

TEST(UpAxis, TheFormatDecidesByDefaultAndTheOptionWins) {
  Scene room = loadScene(test::dataPath("yup_room.gltf").string());
  EXPECT_EQ(room.upAxis, 1);  // glTF
  EXPECT_EQ(applyUpChoice(room, UpChoice::Format), "");
  EXPECT_EQ(room.upAxis, 1);
  EXPECT_EQ(applyUpChoice(room, UpChoice::X), "");
  EXPECT_EQ(room.upAxis, 0);
  EXPECT_EQ(applyUpChoice(room, UpChoice::Auto), "--up auto: y is up (the axis along which the floor faces up at the "
                                                  "bottom and the lights face down)");
  EXPECT_EQ(room.upAxis, 1);
  EXPECT_EQ(loadScene("office").upAxis, 2);
  EXPECT_EQ(loadScene("cornell").upAxis, 1);
  // MGF does not say: guessed, and said so; glTF does.
  std::vector<std::string> notes;
  const Scene mgf = loadScene(test::dataPath("repaired/mgf_bent_quad.mgf").string(), nullptr, {}, nullptr, UpChoice::Format, &notes);
  EXPECT_EQ(mgf.upAxis, guessUpAxis(mgf));
  EXPECT_EQ(notes, std::vector<std::string>{std::string("MGF does not say which axis is up: ") + upAxisName(mgf.upAxis) +
                                            ", from the geometry as --up auto decides (--up sets it)"});
  notes.clear();
  EXPECT_EQ(loadScene(test::dataPath("repaired/mgf_bent_quad.mgf").string(), nullptr, {}, nullptr, UpChoice::Y, &notes).upAxis, 1);
  EXPECT_TRUE(notes.empty());
  loadScene(test::dataPath("yup_room.gltf").string(), nullptr, {}, nullptr, UpChoice::Format, &notes);
  EXPECT_TRUE(notes.empty());
}

TEST(UpAxis, AutoFindsTheBuiltInScenesUpAxes) {
  EXPECT_EQ(guessUpAxis(loadScene("office")), 2);
  EXPECT_EQ(guessUpAxis(loadScene("two-rooms")), 2);
  EXPECT_EQ(guessUpAxis(loadScene("cornell")), 1);
  EXPECT_EQ(guessUpAxis(loadScene(test::dataPath("yup_room.gltf").string())), 1);
}

TEST(UpAxis, AutoFindsTheSameSceneUpAfterAnyTurn) {
  Scene office = loadScene("office");
  for (Polygon& p : office.polygons)
    for (Vec3& v : p.vertices) v = Vec3(v.z, v.x, v.y);  // z up becomes x up
  EXPECT_EQ(guessUpAxis(office), 0);
  for (Polygon& p : office.polygons)
    for (Vec3& v : p.vertices) v = rotateToYUp(v, 0);
  EXPECT_EQ(guessUpAxis(office), 1);
}

// MGF files differ: office3 stands on y (2.71 m high), the others on z. examp1, a lone hanging
// luminaire, has no floor: its end caps face along x at its end but are 2 % of its area.
TEST(UpAxis, AutoFindsTheSharedMgfScenesUp) {
  const std::pair<const char*, int> scenes[] = {{"mgf/cube.mgf", 2},          {"mgf/corridor.mgf", 2},
                                                {"mgf/examp1.mgf", 2},        {"mgf/office2/office2.mgf", 2},
                                                {"mgf/office3/office.mgf", 1}};
  for (const auto& [name, up] : scenes) {
    const std::filesystem::path path = test::sharedPath(std::string("scenes/") + name);
    if (path.empty()) GTEST_SKIP() << "../shared/scenes/" << name << " is absent (it ships beside the project in CI)";
    const Scene scene = loadScene(path.string());
    EXPECT_EQ(guessUpAxis(scene), up) << name;
    EXPECT_EQ(scene.upAxis, up) << name << ": MGF's default";
  }
}

TEST(UpAxis, TurningOntoYUpIsARotationTakingEachFrameOntoYUps) {
  for (int axis = 0; axis < 3; ++axis) {
    const UpFrame from = upFrame(axis), to = upFrame(1);
    EXPECT_EQ(glm::dot(glm::cross(from.across, from.along), from.up), 1.0) << "right-handed, up " << axis;
    EXPECT_EQ(rotateToYUp(from.across, axis), to.across);
    EXPECT_EQ(rotateToYUp(from.along, axis), to.along);
    EXPECT_EQ(rotateToYUp(from.up, axis), Vec3(0, 1, 0));
    const glm::dmat3 m(rotateToYUp({1, 0, 0}, axis), rotateToYUp({0, 1, 0}, axis), rotateToYUp({0, 0, 1}, axis));
    EXPECT_EQ(glm::determinant(m), 1.0) << "no mirror, up " << axis;
  }
  EXPECT_EQ(rotateToYUp({1, 2, 3}, 2), Vec3(1, 3, -2));
  EXPECT_EQ(rotateToYUp({1, 2, 3}, 0), Vec3(2, 1, -3));
}

}  // namespace
}  // namespace radmesh

namespace radmesh {
namespace {

// --sun is placed z up, y north, then turned into the scene's up frame: in the y-up room, north
// is -z (upFrame's along) and the sun overhead shines down -y.
TEST(UpAxis, TheSunFollowsTheScenesUpAxis) {
  Daylight daylight;
  daylight.sun = {parseSun("0,90"), parseSun("0,45")};
  const Scene room = loadScene(test::dataPath("yup_room.gltf").string(), nullptr, daylight);
  ASSERT_EQ(room.upAxis, 1);
  const Light& overhead = room.lights.at(room.lights.size() - 2);
  EXPECT_NEAR(overhead.direction.y, -1.0, 1e-12);
  const Light& north = room.lights.back();  // in the north: its light travels south (+z) and down
  EXPECT_NEAR(north.direction.x, 0.0, 1e-12);
  EXPECT_NEAR(north.direction.y, -std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(north.direction.z, std::sqrt(0.5), 1e-12);
}

}  // namespace
}  // namespace radmesh
