// Reading a bake back: the mesh as written, radiosity from COLOR_0 times radiosityPerColorUnit.
#include "viewer/bake_reader.h"

#include <gtest/gtest.h>

#include <filesystem>

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

std::string tempPath(const char* name) {
  return (std::filesystem::temp_directory_path() / (std::string("radmesh-") + name)).string();
}

TEST(BakeReader, ReadsBackTheMeshAndTheRadiosityBelowSaturation) {
  const DisplayMesh mesh = twoTriangles();
  const std::vector<Rgb> b = {{1.0, 2.0, 3.0}, {0.5, 0.5, 0.5}, {0.25, 0.0, 1.0}, {2.0, 2.0, 2.0}};
  const std::string path = tempPath("bake-reader-test.glb");
  writeBakeGlb(path, mesh, b);
  const std::optional<Bake> bake = readBakeGlb(path);
  std::filesystem::remove(path);
  ASSERT_TRUE(bake.has_value());
  const double unit = bakeRadiosityPerColorUnit(b);
  EXPECT_DOUBLE_EQ(bake->radiosityPerColorUnit, unit);
  ASSERT_EQ(bake->mesh.positions.size(), 4u);
  EXPECT_EQ(bake->mesh.indices, mesh.indices);
  EXPECT_EQ(bake->mesh.patchOfTriangle.size(), 2u);
  for (size_t v = 0; v < 4; ++v) {
    EXPECT_EQ(bake->mesh.positions[v], mesh.positions[v]);
    for (int c = 0; c < 3; ++c)  // COLOR_0 is float: B comes back to float precision, clipped at unit
      EXPECT_NEAR(bake->vertexB[v][c], std::min(b[v][c], unit), 1e-6 * unit) << "vertex " << v << " channel " << c;
  }
}

TEST(BakeReader, AGltfSceneIsNotABake) {
  EXPECT_FALSE(readBakeGlb((test::sourceDir() / "assets" / "cornell.gltf").string()).has_value());
}

TEST(BakeReader, AMissingFileIsASceneErrorNamingIt) {
  try {
    readBakeGlb("/nonexistent/bake.glb");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.file(), "/nonexistent/bake.glb");
  }
}

TEST(BakeReader, TheBakesBrightestFacesTellUp) {
  // A z-up box whose saturated (lamp) face is on the ceiling, facing down.
  DisplayMesh mesh;
  mesh.positions = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 1}, {0, 2, 1}, {2, 2, 1}, {2, 0, 1}};
  mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, -1}, {0, 0, -1}, {0, 0, -1}, {0, 0, -1}};
  mesh.indices = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
  mesh.patchOfTriangle = {0, 0, 1, 1};
  Bake bake{mesh, std::vector<Rgb>(8, Rgb{0.2}), 1.0};
  for (int v = 4; v < 8; ++v) bake.vertexB[v] = Rgb{1.0};
  EXPECT_EQ(bakeFrame(bake).upAxis, 2);
  for (Vec3& p : bake.mesh.positions) p = Vec3(p.x, p.z, -p.y);  // the same box, y-up
  EXPECT_EQ(bakeFrame(bake).upAxis, 1);
}

}  // namespace
}  // namespace radmesh
