// KHR_lights_punctual: types, node transforms, the photometric conversion, and refusals that name
// the light (tests/data/lights/, tests/data/bad/gltf_light_*).
#include <gtest/gtest.h>

#include "solver/io/gltf_import.h"
#include "solver/io/scene_loader.h"
#include "solver/scene/scene_error.h"
#include "tests/solver/io/gltf_test_file.h"
#include "tests/test_paths.h"

namespace radmesh {
namespace {

void expectVec(const Vec3& got, const Vec3& want) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], 1e-12) << "component " << k;
}

TEST(GltfLights, CandelaBecomeWattsPerSteradianAt179LumensPerWatt) {
  EXPECT_EQ(kWhiteEfficacyLmPerW, 179.0);  // the one constant MGF's ed, IES and glTF lights share
  const Scene scene = importGltf(test::dataPath("lights/point_box.gltf").string());
  ASSERT_EQ(scene.lights.size(), 1u);
  const Light& bulb = scene.lights[0];
  EXPECT_EQ(bulb.type, LightType::Point);
  expectVec(bulb.intensity, Rgb(1.0));  // 179 cd white = 1 W/sr per channel
  expectVec(bulb.position, Vec3(1.0, 1.0, 1.0));
  EXPECT_NE(bulb.name.find("'bulb'"), std::string::npos) << bulb.name;
  EXPECT_NE(bulb.name.find("'bulb node'"), std::string::npos) << bulb.name;
}

TEST(GltfLights, ReadsEveryTypeThroughItsNodesWorldTransformAndWarnsOfRange) {
  std::vector<std::string> warnings;
  const Scene scene = importGltf(test::dataPath("lights/three_lights.gltf").string(), &warnings);
  ASSERT_EQ(scene.lights.size(), 3u);
  const Light& lamp = scene.lights[0];
  EXPECT_EQ(lamp.type, LightType::Point);
  expectVec(lamp.position, Vec3(1.0, 1.0, 1.5));        // rig (0.5, 0.25, 0) + node (0.5, 0.75, 1.5)
  expectVec(lamp.intensity, Rgb(2.0, 1.0, 0.5));        // 358 cd x color (1, 0.5, 0.25) / 179
  const Light& spot = scene.lights[1];
  EXPECT_EQ(spot.type, LightType::Spot);
  expectVec(spot.position, Vec3(1.0, 1.75, 1.0));
  expectVec(spot.direction, Vec3(0.0, -1.0, 0.0));      // -90 degrees about x turns -Z into -Y
  EXPECT_DOUBLE_EQ(spot.innerConeRad, 0.3);
  EXPECT_DOUBLE_EQ(spot.outerConeRad, 0.6);
  const Light& sun = scene.lights[2];
  EXPECT_EQ(sun.type, LightType::Directional);
  expectVec(sun.direction, Vec3(0.0, 0.0, -1.0));       // the node's -Z
  expectVec(sun.intensity, Rgb(100.0));                 // 17900 lux / 179 = 100 W/m^2
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("1 KHR_lights_punctual light(s) with a range"), std::string::npos) << warnings[0];
}

std::string lightRefusalAt(const std::string& path) {
  try {
    loadScene(path);
  } catch (const SceneError& e) {
    EXPECT_EQ(e.file(), path);
    return e.element() + " | " + e.what();
  }
  ADD_FAILURE() << path << " was accepted";
  return {};
}

std::string lightRefusal(const std::string& name) { return lightRefusalAt(test::dataPath("bad/" + name).string()); }

TEST(GltfLights, BrokenLightsAreRefusedNamingTheLight) {
  const std::string noType = lightRefusal("gltf_light_no_type.gltf");
  EXPECT_NE(noType.find("KHR_lights_punctual light 0 'bulb' |"), std::string::npos) << noType;
  EXPECT_NE(noType.find("no type"), std::string::npos) << noType;
  const std::string unknown = lightRefusal("gltf_light_unknown_type.gltf");
  EXPECT_NE(unknown.find("light 0 'panel' (node 1 'bulb node')"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("type 'area'"), std::string::npos) << unknown;
  const std::string negative = lightRefusal("gltf_light_negative_intensity.gltf");
  EXPECT_NE(negative.find("light 0 'bulb'"), std::string::npos) << negative;
  EXPECT_NE(negative.find("intensity -5"), std::string::npos) << negative;
  // JSON has no NaN or infinity: 1e999 is refused by the JSON reader.
  EXPECT_NE(lightRefusal("gltf_light_infinite_intensity.gltf").find("1e999"), std::string::npos);
}

// Intensity and colour are checked each, not only their product: -10 x -1 is not a 10 cd light.
TEST(GltfLights, NegativeIntensityTimesNegativeColourIsRefused) {
  test::TempDir dir;
  test::GltfBuilder b;
  const int lamp = b.add("materials", {{"emissiveFactor", {1, 1, 1}}});
  b.addTriangles("t", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, lamp);
  b.doc()["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"name", "bulb"}, {"type", "point"}, {"intensity", -10}, {"color", {-1, -1, -1}}}};
  b.add("nodes", {{"name", "bulb node"}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  const std::string both = lightRefusalAt(b.write(dir / "both.gltf").string());
  EXPECT_NE(both.find("light 0 'bulb' (node 1 'bulb node')"), std::string::npos) << both;
  EXPECT_NE(both.find("intensity -10 is negative"), std::string::npos) << both;
  b.doc()["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = 10;
  const std::string colour = lightRefusalAt(b.write(dir / "colour.gltf").string());
  EXPECT_NE(colour.find("color -1 is negative"), std::string::npos) << colour;
}

// tinygltf would keep the default for a mistyped property (an intensity "1000" became 1 cd) and
// drop a node's light that is no index: each is refused, naming the light or node.
TEST(GltfLights, APropertyOfTheWrongTypeIsRefusedNotDefaulted) {
  test::TempDir dir;
  test::GltfBuilder b;
  const int lamp = b.add("materials", {{"emissiveFactor", {1, 1, 1}}});
  b.addTriangles("t", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, lamp);
  b.doc()["extensions"]["KHR_lights_punctual"]["lights"] = {{{"name", "bulb"}, {"type", "point"}, {"intensity", "1000"}}};
  b.add("nodes", {{"name", "bulb node"}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  std::string what = lightRefusalAt(b.write(dir / "string.gltf").string());
  EXPECT_NE(what.find("KHR_lights_punctual light 0 'bulb': intensity is \"1000\" (string), not a number"),
            std::string::npos)
      << what;
  b.doc()["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = 1000;
  b.doc()["extensions"]["KHR_lights_punctual"]["lights"][0]["color"] = {1, "1", 1};
  what = lightRefusalAt(b.write(dir / "colour.gltf").string());
  EXPECT_NE(what.find("color is [1,\"1\",1] (array), not 3 numbers"), std::string::npos) << what;
  b.doc()["extensions"]["KHR_lights_punctual"]["lights"][0].erase("color");
  b.doc()["nodes"][1]["extensions"]["KHR_lights_punctual"]["light"] = "0";
  what = lightRefusalAt(b.write(dir / "node.gltf").string());
  EXPECT_NE(what.find("node 1 'bulb node': extensions.KHR_lights_punctual.light is \"0\" (string), not a whole number"),
            std::string::npos)
      << what;
  b.doc()["nodes"][1]["extensions"]["KHR_lights_punctual"]["light"] = 0;
  EXPECT_EQ(importGltf(b.write(dir / "fine.gltf").string()).lights.size(), 1u);
}

TEST(GltfLights, ValidationNamesALightWithNaNIntensityOrImpossibleCone) {
  Scene scene = importGltf(test::dataPath("lights/point_box.gltf").string());
  scene.lights[0].intensity.g = std::nan("");
  try {
    validateScene(scene);
    ADD_FAILURE() << "NaN intensity accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(e.element().find("'bulb'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("NaN"), std::string::npos) << e.what();
  }
  scene.lights[0].intensity = Rgb(1.0);
  scene.lights[0].type = LightType::Spot;
  scene.lights[0].innerConeRad = 0.7;
  scene.lights[0].outerConeRad = 0.6;
  EXPECT_THROW(validateScene(scene), SceneError);
  scene.lights[0].innerConeRad = 0.0;
  validateScene(scene);  // a scene lit by its lights alone is solvable
}

}  // namespace
}  // namespace radmesh
