#include "solver/bake/gltf_export.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cstring>
#include <optional>

#include "solver/bake/bake_reader.h"
#include "solver/scene/scene_error.h"
#include "solver/scene/up_axis.h"
#include "tests/solver/io/gltf_test_file.h"

namespace radmesh {
namespace {

using test::TempDir;

// Two triangles of a 2 m x 1 m quad lifted to z = 3, and a lone triangle facing +x.
DisplayMesh sampleMesh() {
  DisplayMesh m;
  m.positions = {{0, 0, 3}, {2, 0, 3}, {2, 1, 3}, {0, 1, 3}, {5, -1, 0}, {5, 0, 0}, {5, 0, 1}};
  m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {2, 0, 0}, {2, 0, 0}, {2, 0, 0}};  // not unit
  m.indices = {0, 1, 2, 0, 2, 3, 4, 5, 6};
  return m;
}

std::vector<Vec3> readVec3(const tinygltf::Model& model, int accessor) {
  const tinygltf::Accessor& a = model.accessors.at(accessor);
  EXPECT_EQ(a.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
  EXPECT_EQ(a.type, TINYGLTF_TYPE_VEC3);
  const tinygltf::BufferView& v = model.bufferViews.at(a.bufferView);
  std::vector<float> f(3 * a.count);
  std::memcpy(f.data(), model.buffers.at(v.buffer).data.data() + v.byteOffset + a.byteOffset, f.size() * sizeof(float));
  std::vector<Vec3> out;
  for (size_t i = 0; i < a.count; ++i) out.emplace_back(f[3 * i], f[3 * i + 1], f[3 * i + 2]);
  return out;
}

TEST(GltfExport, BakeOfAZUpSceneReadsBackYUpWithItsColoursAndUnlitMaterial) {
  TempDir dir;
  const DisplayMesh mesh = sampleMesh();
  // 7 vertices; the 90th percentile of the largest channels (1, 2, 3, 4, 5, 6, 60) is the 6th
  // smallest, 6 W/m^2: that is the colour 1, and the 60 W/m^2 light saturates.
  const std::vector<Rgb> b = {{1, 0.5, 0}, {2, 1, 0}, {3, 0, 0}, {0, 4, 0}, {0, 0, 5}, {6, 3, 1.5}, {60, 30, 15}};
  ASSERT_EQ(bakeRadiosityPerColorUnit(b), 6.0);
  const std::string path = (dir / "bake.glb").string();
  writeBakeGlb(path, mesh, b, /*sceneUpAxis=*/2);

  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string error, warning;
  ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, path)) << error;
  EXPECT_TRUE(error.empty()) << error;
  ASSERT_EQ(model.meshes.size(), 1u);
  ASSERT_EQ(model.meshes[0].primitives.size(), 1u);
  const tinygltf::Primitive& prim = model.meshes[0].primitives[0];
  EXPECT_EQ(prim.mode, TINYGLTF_MODE_TRIANGLES);

  const tinygltf::Accessor& position = model.accessors.at(prim.attributes.at("POSITION"));
  EXPECT_EQ(position.count, 7u);
  // (x, y, z) -> (x, z, -y): the quad's height 3 along glTF's up, y.
  EXPECT_EQ(position.minValues, (std::vector<double>{0, 0, -1}));
  EXPECT_EQ(position.maxValues, (std::vector<double>{5, 3, 1}));
  const std::vector<Vec3> positions = readVec3(model, prim.attributes.at("POSITION"));
  EXPECT_EQ(positions[2], Vec3(2, 3, -1));
  EXPECT_EQ(positions[4], Vec3(5, 0, 1));
  const std::vector<Vec3> normals = readVec3(model, prim.attributes.at("NORMAL"));
  EXPECT_EQ(normals[0], Vec3(0, 1, 0));  // the quad faced up, and still does
  EXPECT_EQ(normals[6], Vec3(1, 0, 0));  // normalised on the way out

  const std::vector<Vec3> colors = readVec3(model, prim.attributes.at("COLOR_0"));
  ASSERT_EQ(colors.size(), 7u);
  EXPECT_EQ(colors[0], Vec3(1.0f / 6.0f, 0.5f / 6.0f, 0.0f));
  EXPECT_EQ(colors[5], Vec3(1.0, 0.5, 0.25));
  EXPECT_EQ(colors[6], Vec3(1.0, 1.0, 1.0));  // clamped

  const tinygltf::Accessor& indices = model.accessors.at(prim.indices);
  EXPECT_EQ(indices.count, 9u);
  EXPECT_EQ(indices.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  const tinygltf::BufferView& view = model.bufferViews.at(indices.bufferView);
  std::vector<uint32_t> read(9);
  std::memcpy(read.data(), model.buffers[0].data.data() + view.byteOffset, 9 * sizeof(uint32_t));
  EXPECT_EQ(read, std::vector<uint32_t>(mesh.indices.begin(), mesh.indices.end()));

  ASSERT_EQ(model.materials.size(), 1u);
  EXPECT_EQ(prim.material, 0);
  EXPECT_TRUE(model.materials[0].extensions.count("KHR_materials_unlit"));
  EXPECT_EQ(model.extensionsUsed, std::vector<std::string>{"KHR_materials_unlit"});
  ASSERT_TRUE(model.meshes[0].extras.Has("radiosityPerColorUnit"));
  EXPECT_EQ(model.meshes[0].extras.Get("radiosityPerColorUnit").GetNumberAsDouble(), 6.0);
  EXPECT_EQ(model.meshes[0].extras.Get("sourceUp").Get<std::string>(), "z");
}

TEST(GltfExport, AYUpSceneIsWrittenAsItIsAndAnXUpOneTurnedWithoutAMirror) {
  TempDir dir;
  const DisplayMesh mesh = sampleMesh();
  const std::vector<Rgb> b(7, Rgb(1.0));
  for (int up : {1, 0}) {
    const std::string path = (dir / "bake.glb").string();
    writeBakeGlb(path, mesh, b, up);
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string error, warning;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, path)) << error;
    const tinygltf::Primitive& prim = model.meshes[0].primitives[0];
    const std::vector<Vec3> positions = readVec3(model, prim.attributes.at("POSITION"));
    const std::vector<Vec3> normals = readVec3(model, prim.attributes.at("NORMAL"));
    if (up == 1) {
      EXPECT_EQ(positions, mesh.positions);
    } else {  // (x, y, z) -> (y, x, -z): x, the scene's up, becomes y
      EXPECT_EQ(positions[4], Vec3(-1, 5, 0));
      EXPECT_EQ(normals[6], Vec3(0, 1, 0));
    }
    // No mirror: the triangle's winding still agrees with its normal.
    const Vec3 winding = glm::cross(positions[5] - positions[4], positions[6] - positions[4]);
    EXPECT_GT(glm::dot(winding, normals[6]), 0.0) << "up " << up;
    EXPECT_EQ(model.meshes[0].extras.Get("sourceUp").Get<std::string>(), up == 1 ? "y" : "x");
  }
}

// A model 1e7 m from the origin keeps its shape: written about its centre with the node translated
// (float positions there snap to whole metres, and half the triangles lost their area), read back
// to within the metres' doubles. Near the origin no translation is written.
TEST(GltfExport, AModelFarFromTheOriginKeepsItsPrecision) {
  TempDir dir;
  DisplayMesh far = sampleMesh();
  const Vec3 away(1e7, -3e6, 250.0);
  for (Vec3& p : far.positions) p += away;
  const std::vector<Rgb> b(far.positions.size(), Rgb(1.0));
  const std::string path = (dir / "far.glb").string();
  writeBakeGlb(path, far, b, /*sceneUpAxis=*/2);
  const std::optional<Bake> read = readBake(path);
  ASSERT_TRUE(read.has_value());
  ASSERT_EQ(read->mesh.positions.size(), far.positions.size());
  for (size_t i = 0; i < far.positions.size(); ++i)
    EXPECT_LT(glm::distance(read->mesh.positions[i], rotateToYUp(far.positions[i], 2)), 1e-6) << i;

  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string error, warning;
  ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, path)) << error;
  ASSERT_EQ(model.nodes.size(), 1u);
  EXPECT_EQ(model.nodes[0].translation.size(), 3u);  // what a stock viewer applies too
  const std::string near = (dir / "near.glb").string();
  writeBakeGlb(near, sampleMesh(), b, 2);
  ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, near)) << error;
  EXPECT_TRUE(model.nodes[0].translation.empty());
}

TEST(GltfExport, ColourScaleFallsBackToTheMaximumThenToOne) {
  std::vector<Rgb> mostlyDark(20, Rgb(0.0));
  mostlyDark[3] = Rgb(0.0, 5.0, 1.0);
  EXPECT_EQ(bakeRadiosityPerColorUnit(mostlyDark), 5.0);
  EXPECT_EQ(bakeRadiosityPerColorUnit(std::vector<Rgb>(4, Rgb(0.0))), 1.0);
}

TEST(GltfExport, UnwritablePathIsAClearError) {
  const std::string path = "/nonexistent-radmesh-dir/bake.glb";
  try {
    writeBakeGlb(path, sampleMesh(), std::vector<Rgb>(7, Rgb(1.0)), 2);
    ADD_FAILURE() << "no error for " << path;
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write the bake to '" + path + "': No such file or directory"),
              std::string::npos)
        << e.what();
  }
}

TEST(GltfExport, RadiosityThatCannotBeTrustedIsNotWritten) {
  TempDir dir;
  const std::string path = (dir / "bad.glb").string();
  EXPECT_THROW(writeBakeGlb(path, sampleMesh(), std::vector<Rgb>(6, Rgb(1.0)), 2), std::invalid_argument);
  std::vector<Rgb> nan(7, Rgb(1.0));
  nan[2].g = std::nan("");
  EXPECT_THROW(writeBakeGlb(path, sampleMesh(), nan, 2), std::invalid_argument);
  std::vector<Rgb> negative(7, Rgb(1.0));
  negative[0].b = -1e-3;
  EXPECT_THROW(writeBakeGlb(path, sampleMesh(), negative, 2), std::invalid_argument);
  // Finite, but inf as a float: the bake would not read back.
  std::vector<Rgb> huge(7, Rgb(1.0));
  huge[4].r = 1e39;
  try {
    writeBakeGlb(path, sampleMesh(), huge, 2);
    ADD_FAILURE() << "a radiosity beyond a float was written";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("a vertex radiosity of 1e+39 W/m^2 is beyond what a bake's 32-bit floats "
                                         "hold (3.4e+38): the bake is not written"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace radmesh
