#include "solver/scene/scene.h"

#include <gtest/gtest.h>

#include "solver/io/scene_loader.h"
#include "solver/scene/scene_error.h"
#include "tests/solver/io/gltf_test_file.h"
#include "tests/solver/io/mgf_test_scene.h"

namespace radmesh {
namespace {

Scene unitSquareScene() {
  Scene s;
  s.source = "test";
  s.materials.push_back({"light", Rgb(0.5), Rgb(1.0, 2.0, 3.0)});
  s.polygons.push_back({{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}}, 0, "square"});
  return s;
}

TEST(Scene, AreaAndPowerOfARectangle) {
  const Scene s = unitSquareScene();
  EXPECT_DOUBLE_EQ(polygonArea(s.polygons[0].vertices), 2.0);
  EXPECT_DOUBLE_EQ(emittedPowerW(s), 2.0 * 6.0);
  EXPECT_NO_THROW(validateScene(s));
}

TEST(Scene, RefusesNaNNonPlanarZeroAreaAndNoEmitter) {
  Scene nan = unitSquareScene();
  nan.polygons[0].vertices[1].y = std::nan("");
  EXPECT_THROW(validateScene(nan), SceneError);

  Scene bent = unitSquareScene();
  bent.polygons[0].vertices[2].z = 0.2;
  EXPECT_THROW(validateScene(bent), SceneError);

  Scene flat = unitSquareScene();
  flat.polygons[0].vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  EXPECT_THROW(validateScene(flat), SceneError);

  Scene dark = unitSquareScene();
  dark.materials[0].emittance = Rgb(0.0);
  EXPECT_THROW(validateScene(dark), SceneError);

  Scene mirror = unitSquareScene();
  mirror.materials[0].rho = Rgb(1.0);
  EXPECT_THROW(validateScene(mirror), SceneError);
}

// A model so far from the origin that its own coordinates lose their digits is refused, saying how
// far and to what it is known; site coordinates are not. 1e12 m out, a 2 m square's power came out
// 0.02 % off, without a word.
TEST(ValidateScene, AModelTooFarFromTheOriginForItsSizeIsRefused) {
  const auto movedBy = [](const Vec3& by) {
    Scene s = unitSquareScene();
    for (Vec3& v : s.polygons[0].vertices) v += by;
    return s;
  };
  EXPECT_NO_THROW(validateScene(movedBy({512345.678, 5012345.678, 0.0})));
  EXPECT_NO_THROW(validateScene(movedBy({8e6, 0.0, 0.0})));  // 1.8e-9 m: 9e-10 of its 2 m
  for (const double far : {1e12, 1e9, 1e20}) {
    try {
      validateScene(movedBy({far, 0.0, 0.0}));
      ADD_FAILURE() << far << " was accepted";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("where a coordinate is known to"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("move the model near the origin"), std::string::npos) << e.what();
    }
  }
  try {
    validateScene(movedBy({1e12, 0.0, 0.0}));
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("test: lies 1e+12 m from the origin, where a coordinate is known to 0.00022 "
                                         "m only, 0.00011 of the model's 2 m size"),
              std::string::npos)
        << e.what();
  }
}

// MGF's ed 1e308, glTF's emissiveStrength 1e300 and a light of 1e308 cd were solved into a bake
// whose float radiosities are infinite (and which radmesh cannot read back): past 1e30 W/m^2 or
// 1e30 W they are refused, by the one check every format's scene goes through.
TEST(ValidateScene, AnEmitterPastTheTrustedBoundIsRefusedInEveryFormat) {
  const test::TempDir dir;
  const auto refusal = [](const std::string& path) {
    try {
      loadScene(path);
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string fix = " radmesh trusts (no real light comes near; a solve would overflow the bake's radiosities) "
                          "(fix: lower its ";
  const std::string units = " to a real light's: MGF's ed is in lm/m^2, glTF's emission in W/m^2, a glTF light's "
                            "intensity in candela (lux for a directional light))";
  const std::string mgf = test::writeMgf(dir, "lamp.mgf", "m lamp =\n  ed 1e308\nv a =\n  p 0 0 0\nv b =\n  p 1 0 0\n"
                                                          "v c =\n  p 0 1 0\nf a b c\n");
  EXPECT_EQ(refusal(mgf), mgf + ": material 'lamp': emits 5.58659e+305 W/m^2, more than the 1e+30 W/m^2" + fix +
                              "emittance" + units);

  test::GltfBuilder glowing;
  const int lamp = glowing.add("materials", {{"name", "lamp"},
                                             {"emissiveFactor", {1, 1, 1}},
                                             {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 1e300}}}}}});
  glowing.addTriangles("t", glowing.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, lamp);
  const std::string strength = glowing.write(dir / "strength.gltf").string();
  EXPECT_EQ(refusal(strength), strength + ": material 'lamp': emits 1e+300 W/m^2, more than the 1e+30 W/m^2" + fix +
                                   "emittance" + units);

  test::GltfBuilder lit;
  lit.addTriangles("t", lit.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, -1);
  lit.add("nodes", {{"name", "bulb"}, {"translation", {0, 0, 1}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  lit.doc()["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"intensity", 1e308}}};
  const std::string light = lit.write(dir / "light.gltf").string();
  EXPECT_EQ(refusal(light), light + ": KHR_lights_punctual light 0 (node 1 'bulb'): emits 2.1061e+307 W, more than "
                                    "the 1e+30 W" + fix + "intensity" + units);

  // Just below the bound still loads: 1e30 W/m^2 is far past any lamp, not past a float.
  glowing.doc()["materials"][0]["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = 1e30;
  EXPECT_EQ(refusal(glowing.write(dir / "bright.gltf").string()), "accepted");
}

}  // namespace
}  // namespace radmesh
