// Reading a bake back: the mesh as written, radiosity from COLOR_0 times radiosityPerColorUnit.
#include "solver/bake/bake_reader.h"

#include <gtest/gtest.h>

#include <iterator>

#include <tiny_gltf.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "solver/bake/gltf_export.h"
#include "solver/scene/scene_error.h"
#include "tests/test_paths.h"

namespace radmesh {
namespace {

DisplayMesh twoTriangles() {
  DisplayMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  mesh.normals.assign(4, Vec3{0, 0, 1});
  mesh.indices = {0, 1, 2, 0, 2, 3};
  mesh.patchOfTriangle = {0, 0};
  return mesh;
}

// Unique per process: other checkouts may run the same tests at the same time.
std::string tempPath(const char* name) {
  return (std::filesystem::temp_directory_path() / ("radmesh-" + std::to_string(getpid()) + "-" + name)).string();
}

TEST(BakeReader, ReadsBackTheMeshAndTheRadiosityBelowSaturationYUp) {
  const DisplayMesh mesh = twoTriangles();
  const std::vector<Rgb> b = {{1.0, 2.0, 3.0}, {0.5, 0.5, 0.5}, {0.25, 0.0, 1.0}, {2.0, 2.0, 2.0}};
  const std::string path = tempPath("bake-reader-test.glb");
  writeBakeGlb(path, mesh, b, /*sceneUpAxis=*/1);
  const std::optional<Bake> bake = readBake(path);
  std::filesystem::remove(path);
  ASSERT_TRUE(bake.has_value());
  const double unit = bakeRadiosityPerColorUnit(b);
  EXPECT_DOUBLE_EQ(bake->radiosityPerColorUnit, unit);
  EXPECT_EQ(bake->upAxis, 1);
  EXPECT_EQ(bake->sourceUp, 1);
  EXPECT_TRUE(bake->fromRadmesh);
  ASSERT_EQ(bake->mesh.positions.size(), 4u);
  EXPECT_EQ(bake->mesh.indices, mesh.indices);
  EXPECT_EQ(bake->mesh.patchOfTriangle.size(), 2u);
  for (size_t v = 0; v < 4; ++v) {
    EXPECT_EQ(bake->mesh.positions[v], mesh.positions[v]);
    for (int c = 0; c < 3; ++c)  // _RADIOSITY is float: B comes back to float precision, not clipped at unit
      EXPECT_NEAR(bake->vertexB[v][c], b[v][c], 1e-6 * b[v][c]) << "vertex " << v << " channel " << c;
  }
}

// A bake written before _RADIOSITY (COLOR_0 alone) is read as it was: B clipped at the unit.
TEST(BakeReader, ABakeWithoutRadiosityReadsColourTimesItsUnit) {
  const std::vector<Rgb> b = {{1.0, 2.0, 3.0}, {0.5, 0.5, 0.5}, {0.25, 0.0, 1.0}, {2.0, 2.0, 2.0}};
  const std::string path = tempPath("bake-reader-old.glb");
  writeBakeGlb(path, twoTriangles(), b, /*sceneUpAxis=*/1);
  const std::optional<Bake> written = readBake(path);
  ASSERT_TRUE(written.has_value());
  // The same bake as a .gltf without the attribute: rewritten through tinygltf's JSON.
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t at = bytes.find("\"_RADIOSITY\"");
  ASSERT_NE(at, std::string::npos);
  bytes.replace(at, std::string("\"_RADIOSITY\"").size(), "\"_IGNORED__\"");  // same length: the GLB stays whole
  std::ofstream(path, std::ios::binary) << bytes;
  const std::optional<Bake> old = readBake(path);
  std::filesystem::remove(path);
  ASSERT_TRUE(old.has_value());
  const double unit = bakeRadiosityPerColorUnit(b);
  for (size_t v = 0; v < 4; ++v)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(old->vertexB[v][c], std::min(b[v][c], unit), 1e-6 * unit) << "vertex " << v << " channel " << c;
}

TEST(BakeReader, AGltfSceneIsNotABake) {
  EXPECT_FALSE(readBake((test::sourceDir() / "assets" / "cornell.gltf").string()).has_value());
}

TEST(BakeReader, AMissingFileIsASceneErrorNamingIt) {
  try {
    readBake("/nonexistent/bake.glb");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.file(), "/nonexistent/bake.glb");
  }
}

// A bake as radmesh wrote it before bakes were turned y-up: in its scene's axes, no sourceUp.
void writeOldBake(const std::string& path, const DisplayMesh& mesh, const std::vector<Rgb>& b) {
  writeBakeGlb(path, mesh, b, /*sceneUpAxis=*/1);  // y: not turned
  tinygltf::TinyGLTF gltf;
  tinygltf::Model model;
  std::string error, warning;
  ASSERT_TRUE(gltf.LoadBinaryFromFile(&model, &error, &warning, path)) << error;
  tinygltf::Value::Object extras = model.meshes[0].extras.Get<tinygltf::Value::Object>();
  extras.erase("sourceUp");
  model.meshes[0].extras = tinygltf::Value(extras);
  ASSERT_TRUE(gltf.WriteGltfSceneToFile(&model, path, true, true, false, /*writeBinary=*/true));
}

TEST(BakeReader, AnOldBakesUpAxisIsGuessedWithItsBrightestFacesAsLights) {
  // A box's floor and, saturated like a lamp, its ceiling, facing each other along z.
  DisplayMesh mesh;
  mesh.positions = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 1}, {0, 2, 1}, {2, 2, 1}, {2, 0, 1}};
  mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, -1}, {0, 0, -1}, {0, 0, -1}, {0, 0, -1}};
  mesh.indices = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
  std::vector<Rgb> b(8, Rgb{0.2});
  for (int v = 4; v < 8; ++v) b[v] = Rgb{5.0};
  const std::string path = tempPath("old-bake-test.glb");
  writeOldBake(path, mesh, b);
  std::optional<Bake> bake = readBake(path);
  ASSERT_TRUE(bake.has_value());
  EXPECT_EQ(bake->sourceUp, -1);
  EXPECT_EQ(bake->upAxis, 2);
  const Scene scene = bakeScene(*bake, path);
  EXPECT_EQ(scene.materials.at(scene.polygons[2].material).emits(), true);  // the ceiling, saturated
  EXPECT_EQ(scene.materials.at(scene.polygons[0].material).emits(), false);

  for (Vec3& p : mesh.positions) p = Vec3(p.x, p.z, -p.y);  // the same box, y-up
  for (Vec3& n : mesh.normals) n = Vec3(n.x, n.z, -n.y);
  writeOldBake(path, mesh, b);
  bake = readBake(path);
  std::filesystem::remove(path);
  ASSERT_TRUE(bake.has_value());
  EXPECT_EQ(bake->upAxis, 1);
}

TEST(BakeReader, AnotherToolsBakeIsItsColouredTrianglesInWorldSpace) {
  const std::string path = test::dataPath("other_tool_bake.gltf").string();
  const std::optional<Bake> bake = readBake(path);
  ASSERT_TRUE(bake.has_value());
  EXPECT_FALSE(bake->fromRadmesh);
  EXPECT_EQ(bake->upAxis, 1);  // glTF's
  EXPECT_EQ(bake->sourceUp, -1);
  EXPECT_EQ(bake->radiosityPerColorUnit, 1.0);
  ASSERT_EQ(bake->mesh.indices.size(), 12u);  // two quads, as triangles, each vertex its own
  ASSERT_EQ(bake->vertexB.size(), 12u);
  EXPECT_EQ(bake->mesh.positions[0], Vec3(1, 0, 0));  // the node moves it 1 m along x
  EXPECT_EQ(bake->mesh.normals[0], Vec3(0, 1, 0));    // the floor faces up
  EXPECT_EQ(bake->vertexB[0], Rgb(1.0, 128.0 / 255.0, 0.0));  // normalized bytes; alpha dropped
  EXPECT_EQ(bake->mesh.normals[6], Vec3(0, 0, 1));
  EXPECT_EQ(bake->vertexB[6], Rgb(0.2, 0.4, 0.8));
  EXPECT_DOUBLE_EQ(totalArea(bakeScene(*bake, path).polygons), 8.0);
}

TEST(BakeReader, VertexColoursWithALightOrWithAnUncolouredPrimitiveAreAScene) {
  nlohmann::json gltf = nlohmann::json::parse(std::ifstream(test::dataPath("other_tool_bake.gltf")));
  const std::string path = tempPath("coloured-scene.gltf");
  nlohmann::json lit = gltf;
  lit["materials"][0]["emissiveFactor"] = {1.0, 1.0, 1.0};
  std::ofstream(path) << lit.dump();
  EXPECT_FALSE(readBake(path).has_value());
  nlohmann::json partly = gltf;
  partly["meshes"][0]["primitives"][1]["attributes"].erase("COLOR_0");
  std::ofstream(path) << partly.dump();
  EXPECT_FALSE(readBake(path).has_value());
  std::filesystem::remove(path);
}

TEST(BakeReader, OnlyGltfFilesCanBeBakes) {
  EXPECT_FALSE(readBake("office").has_value());
  EXPECT_FALSE(readBake(test::dataPath("repaired/mgf_bent_quad.mgf").string()).has_value());
}

}  // namespace
}  // namespace radmesh
