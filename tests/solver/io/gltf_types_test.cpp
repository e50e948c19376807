// A glTF property of the wrong JSON type is refused naming its element (checkGltfTypes): tinygltf
// would put its default in its place and load wrong geometry or numbers without a word.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "solver/io/gltf_import.h"
#include "solver/scene/scene_error.h"
#include "tests/solver/io/gltf_test_file.h"

namespace radmesh {
namespace {

using nlohmann::json;

// The audit's room: a closed 2 m box (24 positions, 36 indices) in material 0 'wall', and a
// 0.4 m square lamp just below its ceiling in material 1 'lamp'. The document, as written.
json roomDocument(const test::TempDir& dir) {
  const double s = 2.0, y = 1.99;
  std::vector<Vec3> walls;
  std::vector<uint32_t> indices;
  for (const std::vector<Vec3>& quad : std::vector<std::vector<Vec3>>{{{0, 0, 0}, {0, 0, s}, {s, 0, s}, {s, 0, 0}},
                                                                      {{0, s, 0}, {s, s, 0}, {s, s, s}, {0, s, s}},
                                                                      {{0, 0, 0}, {s, 0, 0}, {s, s, 0}, {0, s, 0}},
                                                                      {{0, 0, s}, {0, s, s}, {s, s, s}, {s, 0, s}},
                                                                      {{0, 0, 0}, {0, s, 0}, {0, s, s}, {0, 0, s}},
                                                                      {{s, 0, 0}, {s, 0, s}, {s, s, s}, {s, s, 0}}}) {
    const uint32_t n = static_cast<uint32_t>(walls.size());
    walls.insert(walls.end(), quad.begin(), quad.end());
    indices.insert(indices.end(), {n, n + 1, n + 2, n, n + 2, n + 3});
  }
  test::GltfBuilder b;
  const int wall =
      b.add("materials", {{"name", "wall"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.6, 0.6, 0.6, 1}}}}});
  const int lamp = b.add("materials", {{"name", "lamp"}, {"emissiveFactor", {1, 1, 1}}});
  b.addTriangles("room", b.addPositions(walls), b.addIndices(indices, 5123), wall, {{"name", "room"}});
  b.addTriangles("lamp", b.addPositions({{0.8, y, 0.8}, {1.2, y, 0.8}, {1.2, y, 1.2}, {0.8, y, 1.2}}),
                 b.addIndices({0, 1, 2, 0, 2, 3}, 5123), lamp);
  std::ifstream in(b.write(dir / "room.gltf"));
  return json::parse(in);
}

std::string writeDocument(const test::TempDir& dir, const std::string& name, const json& doc) {
  const std::string path = (dir / name).string();
  std::ofstream(path) << doc.dump();
  return path;
}

std::string repeated(const std::string& text, int times) {
  std::string out;
  for (int k = 0; k < times; ++k) out += text;
  return out;
}

// What importGltf says of the file: its element, then its message after the file's name.
std::string typeRefusal(const std::string& path) {
  try {
    importGltf(path);
  } catch (const SceneError& e) {
    EXPECT_EQ(e.file(), path);
    const std::string what = e.what();
    const std::string prefix = path + ": " + (e.element().empty() ? "" : e.element() + ": ");
    EXPECT_EQ(what.substr(0, prefix.size()), prefix);
    return e.element() + " | " + what.substr(std::min(what.size(), prefix.size()));
  }
  ADD_FAILURE() << path << " was accepted";
  return {};
}

TEST(GltfTypes, TheRoomLoadsWithItsIndexBufferAndTransforms) {
  test::TempDir dir;
  json doc = roomDocument(dir);
  Scene scene = importGltf(writeDocument(dir, "room.gltf", doc));
  EXPECT_EQ(scene.polygons.size(), 7u);  // six walls and the lamp
  EXPECT_NEAR(totalArea(scene.polygons), 24.16, 1e-6);  // the lamp's corners are floats
  // Integers written as floats where numbers are wanted are numbers all the same.
  doc["nodes"][0]["translation"] = {1.0, 0, 0};
  doc["materials"][1]["emissiveFactor"] = {1.0, 1, 1};
  // glTF's schema gives a primitive no name: one of any type is none of radmesh's business.
  doc["meshes"][0]["primitives"][0]["name"] = 5;
  scene = importGltf(writeDocument(dir, "moved.gltf", doc));
  ASSERT_EQ(scene.polygons.size(), 7u);
  double lowestX = 1e9;
  for (const Polygon& p : scene.polygons)
    if (p.origin.starts_with("mesh 'room'"))
      for (const Vec3& v : p.vertices) lowestX = std::min(lowestX, v.x);
  EXPECT_DOUBLE_EQ(lowestX, 1.0);
}

struct Mistyped {
  std::function<void(json&)> change;
  std::string refusal;  // element | message, fix included
};

TEST(GltfTypes, APropertyOfTheWrongTypeIsRefusedNamingItsElement) {
  test::TempDir dir;
  const std::string whole = "a whole number from 0 to 2147483647";
  const std::string wholes = "whole numbers from 0 to 2147483647";
  const std::vector<Mistyped> cases = {
      // An index: a string, a fraction, negative, and past the int tinygltf reads it into (where
      // 4294967296 became mesh 0).
      {[](json& d) { d["meshes"][0]["primitives"][0]["indices"] = "1"; },
       "mesh 0 'room' primitive 0 | indices is \"1\" (string), not " + whole + " (fix: give indices as " + whole + ")"},
      {[](json& d) { d["meshes"][0]["primitives"][0]["indices"] = 1.0; },
       "mesh 0 'room' primitive 0 | indices is 1.0 (number), not " + whole + " (fix: give indices as " + whole +
           ": 1, without a decimal point or sign)"},
      {[](json& d) { d["meshes"][0]["primitives"][0]["indices"] = 1.5; },
       "mesh 0 'room' primitive 0 | indices is 1.5 (number), not " + whole + " (fix: give indices as " + whole + ")"},
      {[](json& d) { d["meshes"][1]["primitives"][0]["material"] = "1"; },
       "mesh 1 'lamp' primitive 0 | material is \"1\" (string), not " + whole},
      {[](json& d) { d["nodes"][0]["mesh"] = -1; }, "node 0 'room' | mesh is -1 (number), not " + whole},
      {[](json& d) { d["nodes"][0]["mesh"] = 4294967296; },
       "node 0 'room' | mesh is 4294967296 (number), not " + whole},
      {[](json& d) { d["scene"] = "0"; }, " | scene is \"0\" (string), not " + whole},
      {[](json& d) { d["bufferViews"][1]["buffer"] = "0"; }, "bufferView 1 | buffer is \"0\" (string), not " + whole},
      {[](json& d) { d["textures"] = json::array({json{{"source", "0"}}}); },
       "texture 0 | source is \"0\" (string), not " + whole},
      {[](json& d) { d["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = "0"; },
       "mesh 0 'room' primitive 0 | attributes is {\"POSITION\":\"0\"} (object), not an object of " + wholes},
      {[](json& d) { d["scenes"][0]["nodes"] = {0, "1"}; },
       "scene 0 | nodes is [0,\"1\"] (array), not an array of " + wholes},
      // A size or count.
      {[](json& d) { d["accessors"][1]["count"] = "36"; },
       "accessor 1 | count is \"36\" (string), not a whole number >= 0 (fix: give count as a whole number >= 0)"},
      {[](json& d) { d["bufferViews"][0]["byteOffset"] = -4; },
       "bufferView 0 | byteOffset is -4 (number), not a whole number >= 0 (fix: give byteOffset as a whole number >= 0)"},
      // A number array of its length, short, empty (read as absent) or holding a string.
      {[](json& d) { d["nodes"][0]["translation"] = {"a", 0, 0}; },
       "node 0 'room' | translation is [\"a\",0,0] (array), not 3 numbers (fix: give translation as 3 numbers)"},
      {[](json& d) { d["nodes"][0]["scale"] = {1, 1}; }, "node 0 'room' | scale is [1,1] (array), not 3 numbers"},
      {[](json& d) { d["nodes"][0]["rotation"] = json::array(); },
       "node 0 'room' | rotation is [] (array), not 4 numbers"},
      {[](json& d) { d["nodes"][0]["matrix"] = std::vector<int>(15, 0); },
       "node 0 'room' | matrix is [0,0,0,0,0,0,0,0,0,0,0,0,0,0,0] (array), not 16 numbers"},
      {[](json& d) { d["materials"][1]["emissiveFactor"] = {"a", 1, 1}; },
       "material 1 'lamp' | emissiveFactor is [\"a\",1,1] (array), not 3 numbers"},
      {[](json& d) { d["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {"a", 0.2, 0.2, 1}; },
       "material 0 'wall' | pbrMetallicRoughness.baseColorFactor is [\"a\",0.2,0.2,1] (array), not 4 numbers"},
      // A number, a string, a boolean.
      {[](json& d) { d["materials"][1]["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = "5"; },
       "material 1 'lamp' | extensions.KHR_materials_emissive_strength.emissiveStrength is \"5\" (string), not a "
       "number"},
      {[](json& d) { d["accessors"][0]["type"] = 3; }, "accessor 0 | type is 3 (number), not a string"},
      {[](json& d) { d["buffers"][0]["uri"] = 5; }, "buffer 0 | uri is 5 (number), not a string"},
      {[](json& d) { d["materials"][0]["doubleSided"] = "yes"; },
       "material 0 'wall' | doubleSided is \"yes\" (string), not true or false (fix: give doubleSided as true or "
       "false)"},
      // The name every element but a primitive may have (tinygltf dropped a name that is no string).
      {[](json& d) { d["nodes"][0]["name"] = 5; },
       "node 0 | name is 5 (number), not a string (fix: give name as a string)"},
      {[](json& d) { d["meshes"][1]["name"] = json::object(); }, "mesh 1 | name is {} (object), not a string"},
      {[](json& d) { d["materials"][0]["name"] = json::array({"wall"}); },
       "material 0 | name is [\"wall\"] (array), not a string"},
      {[](json& d) { d["accessors"][0]["name"] = true; }, "accessor 0 | name is true (boolean), not a string"},
      {[](json& d) { d["scenes"][0]["name"] = nullptr; }, "scene 0 | name is null (null), not a string"},
      // An object on the way to a property, and the document's arrays of elements.
      {[](json& d) { d["materials"][0]["pbrMetallicRoughness"] = 5; },
       "material 0 'wall' | pbrMetallicRoughness is 5 (number), not an object (fix: give pbrMetallicRoughness as an "
       "object)"},
      {[](json& d) { d["images"] = {"room.png"}; }, " | images is [\"room.png\"] (array), not an array of objects"},
      {[](json& d) { d["meshes"][0]["primitives"] = json::object(); },
       "mesh 0 'room' | primitives is {} (object), not an array of objects"},
      // A long value is cut short.
      {[](json& d) { d["nodes"][0]["children"] = std::vector<std::string>(40, "1"); },
       "node 0 'room' | children is [" + repeated("\"1\",", 14) + "\"1\"... (array), not an array of " + wholes},
  };
  const json room = roomDocument(dir);
  for (size_t i = 0; i < cases.size(); ++i) {
    json doc = room;
    cases[i].change(doc);
    const std::string got = typeRefusal(writeDocument(dir, "case" + std::to_string(i) + ".gltf", doc));
    EXPECT_EQ(got.substr(0, cases[i].refusal.size()), cases[i].refusal) << "case " << i;
  }
}

// A count written -0 is refused as tinygltf would (its integers are unsigned) and shown as the file
// writes it: it read "count is 0, not a whole number >= 0".
TEST(GltfTypes, AMinusZeroCountIsShownAsWrittenWithHowToWriteIt) {
  test::TempDir dir;
  json doc = roomDocument(dir);
  doc["accessors"][1]["count"] = 987654321;  // a mark to write -0 over
  const std::string path = writeDocument(dir, "minus-zero.gltf", doc);
  std::stringstream text;
  text << std::ifstream(path).rdbuf();
  std::string written = text.str();
  written.replace(written.find("987654321"), 9, "-0");
  std::ofstream(path) << written;
  EXPECT_EQ(typeRefusal(path), "accessor 1 | count is -0 (number), not a whole number >= 0 (fix: give count as a whole "
                               "number >= 0: 0, without a decimal point or sign)");
}

// A node's light must name its light: tinygltf ignored an extension without one.
TEST(GltfTypes, ANodesLightExtensionWithoutItsLightIsRefused) {
  test::TempDir dir;
  json doc = roomDocument(dir);
  doc["extensions"]["KHR_lights_punctual"]["lights"] = json::array({json{{"type", "point"}, {"intensity", 100}}});
  doc["nodes"].push_back({{"translation", {1, 1.5, 1}}, {"extensions", {{"KHR_lights_punctual", json::object()}}}});
  doc["scenes"][0]["nodes"].push_back(2);
  EXPECT_EQ(typeRefusal(writeDocument(dir, "nolight.gltf", doc)),
            "node 2 | extensions.KHR_lights_punctual.light is missing (it must be a whole number from 0 to "
            "2147483647) (fix: give extensions.KHR_lights_punctual.light as a whole number from 0 to 2147483647)");
  doc["nodes"][2]["extensions"]["KHR_lights_punctual"]["light"] = 0;
  const Scene scene = importGltf(writeDocument(dir, "light.gltf", doc));
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].position, Vec3(1, 1.5, 1));
  EXPECT_EQ(scene.polygons.size(), 7u);
}

// Of the right type but naming nothing: tinygltf refuses these without naming the primitive or image.
TEST(GltfTypes, AnIndexBufferOrImageViewNamingNothingIsRefusedNamingItsUser) {
  test::TempDir dir;
  json doc = roomDocument(dir);
  doc["meshes"][0]["primitives"][0]["indices"] = 99;
  std::string got = typeRefusal(writeDocument(dir, "indices.gltf", doc));
  EXPECT_EQ(got.substr(0, got.find(" | ")), "mesh 0 'room' primitive 0") << got;
  EXPECT_NE(got.find("indices 99 names none of the file's 4 accessors (fix: refer to an existing accessor"),
            std::string::npos)
      << got;
  doc = roomDocument(dir);
  doc["images"] = json::array({json{{"bufferView", 9}, {"mimeType", "image/png"}}});
  got = typeRefusal(writeDocument(dir, "image.gltf", doc));
  EXPECT_EQ(got.substr(0, got.find(" | ")), "image 0") << got;
  EXPECT_NE(got.find("bufferView 9 names none of the file's 4 bufferViews"), std::string::npos) << got;
}

// JSON has no infinity: 1e999 is refused by the JSON reader (nlohmann's, as tinygltf's), not read as inf.
TEST(GltfTypes, ANumberBeyondDoublesIsRefusedAsJson) {
  test::TempDir dir;
  json doc = roomDocument(dir);
  doc["nodes"][0]["translation"] = {12345, 0, 0};
  std::string text = doc.dump();
  text.replace(text.find("12345"), 5, "1e999");
  const std::string path = (dir / "inf.gltf").string();
  std::ofstream(path) << text;
  const std::string got = typeRefusal(path);
  EXPECT_EQ(got.substr(0, 7), "JSON | ") << got;
  EXPECT_NE(got.find("number overflow parsing '1e999'"), std::string::npos) << got;
}

}  // namespace
}  // namespace radmesh
