#include "solver/io/gltf_import.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "solver/bake/display_radiosity.h"
#include "solver/bake/gltf_export.h"
#include "solver/scene/scene_error.h"
#include "tests/solver/io/gltf_test_file.h"
#include "tests/test_paths.h"

namespace radmesh {
namespace {

using test::GltfBuilder;
using test::TempDir;

const std::vector<Vec3> kQuadVertices = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};

bool mentions(const std::vector<std::string>& warnings, const std::string& text) {
  return std::any_of(warnings.begin(), warnings.end(),
                     [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

TEST(GltfImport, CornellBoxHasThePublishedGeometryAndOneLight) {
  const std::string path = (test::sourceDir() / "assets" / "cornell.gltf").string();
  std::vector<std::string> warnings;
  const Scene scene = importGltf(path, &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_NO_THROW(validateScene(scene));
  // floor 1, ceiling 4 (around the light), light 1, back 1, right 1, left 2 (published
  // non-planar, so its two triangles stay apart), short block 5, tall block 5.
  EXPECT_EQ(scene.polygons.size(), 20u);
  EXPECT_EQ(scene.materials.size(), 4u);

  Vec3 lo{1e9}, hi{-1e9};
  int emitters = 0;
  double lightAreaM2 = 0.0;
  for (const Polygon& p : scene.polygons) {
    for (const Vec3& v : p.vertices) {
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
    if (scene.materials[p.material].emits()) {
      ++emitters;
      lightAreaM2 += polygonArea(p.vertices);
    }
  }
  EXPECT_EQ(emitters, 1);
  EXPECT_NEAR(lightAreaM2, 0.130 * 0.105, 1e-8);  // 130 mm x 105 mm
  ASSERT_EQ(scene.materials[3].name, "light");
  const Rgb e = scene.materials[3].emittance;
  EXPECT_NEAR(e.r, glm::pi<double>() * 17.0, 1e-9);  // E = pi L, L = (17, 12, 4) W/(m^2 sr)
  EXPECT_NEAR(e.g, glm::pi<double>() * 12.0, 1e-9);
  EXPECT_NEAR(e.b, glm::pi<double>() * 4.0, 1e-9);
  EXPECT_NEAR(emittedPowerW(scene), lightAreaM2 * (e.r + e.g + e.b), 1e-12);
  EXPECT_NEAR(emittedPowerW(scene), 0.01365 * 33.0 * glm::pi<double>(), 1e-6);  // 1.415 W

  // Millimetres became metres: 556.0 x 548.8 x 559.2 mm.
  EXPECT_NEAR(lo.x, 0.0, 1e-7);
  EXPECT_NEAR(lo.y, 0.0, 1e-7);
  EXPECT_NEAR(lo.z, 0.0, 1e-7);
  EXPECT_NEAR(hi.x, 0.5560, 1e-7);
  EXPECT_NEAR(hi.y, 0.5488, 1e-7);
  EXPECT_NEAR(hi.z, 0.5592, 1e-7);

  // Every surface faces into the box: the shell towards its middle, each block's faces away from
  // that block's centre.
  auto centroidOf = [](const std::vector<Vec3>& points) {
    Vec3 c{0.0};
    for (const Vec3& v : points) c += v / static_cast<double>(points.size());
    return c;
  };
  for (const Polygon& p : scene.polygons) {
    Vec3 inside = 0.5 * (lo + hi);
    if (p.origin.find("block") != std::string::npos) {
      std::vector<Vec3> block;
      for (const Polygon& q : scene.polygons)
        if (q.origin == p.origin) block.insert(block.end(), q.vertices.begin(), q.vertices.end());
      inside = 2.0 * centroidOf(p.vertices) - centroidOf(block);  // mirror the centre through the face
    }
    EXPECT_GT(glm::dot(newellNormal(p.vertices), inside - centroidOf(p.vertices)), 0.0) << p.origin;
  }
}

TEST(GltfImport, IndexedU8U16U32AndNonIndexedTrianglesGiveTheSameQuad) {
  TempDir dir;
  for (int type : {5121, 5123, 5125, 0}) {
    GltfBuilder b;
    const int lamp = b.add("materials", {{"name", "lamp"}, {"emissiveFactor", {1, 1, 1}}});
    if (type == 0) {
      b.addTriangles("quad", b.addPositions({kQuadVertices[0], kQuadVertices[1], kQuadVertices[2], kQuadVertices[0], kQuadVertices[2], kQuadVertices[3]}), -1, lamp);
    } else {
      b.addTriangles("quad", b.addPositions(kQuadVertices), b.addIndices({0, 1, 2, 0, 2, 3}, type), lamp);
    }
    const Scene s = importGltf(b.write(dir / ("quad" + std::to_string(type) + ".gltf")).string());
    ASSERT_EQ(s.polygons.size(), 1u) << "component type " << type;
    EXPECT_EQ(s.polygons[0].vertices, kQuadVertices) << "component type " << type;
    EXPECT_EQ(s.polygons[0].origin, "mesh 'quad' primitive 0");
  }
}

TEST(GltfImport, NodeTransformsComposeFromTheRootDown) {
  TempDir dir;
  GltfBuilder b;
  const int positions = b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  // Child: a column-major matrix translating by (0, 0, 1). Parent: T(10, 0, 0) R(90 deg about y) S(2).
  const int child = b.addTriangles("t", positions, -1, -1,
                                   {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1}}});
  const double h = std::sqrt(0.5);
  b.add("nodes", {{"name", "parent"},
                  {"translation", {10, 0, 0}},
                  {"rotation", {0, h, 0, h}},
                  {"scale", {2, 2, 2}},
                  {"children", {child}}});
  std::vector<std::string> warnings;
  const Scene s = importGltf(b.write(dir / "nodes.gltf").string(), &warnings);
  ASSERT_EQ(s.polygons.size(), 1u);
  // p -> T(R(S(p + (0,0,1)))): R about y maps (x, y, z) to (z, y, -x).
  const std::vector<Vec3> expected = {{12, 0, 0}, {12, 0, -2}, {12, 2, 0}};
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.polygons[0].vertices[k][c], expected[k][c], 1e-12);
  EXPECT_TRUE(mentions(warnings, "without a material")) << "the default grey is announced";
  EXPECT_EQ(s.materials.at(s.polygons[0].material).name, "default (grey)");
}

// A rotation quaternion must be unit length; one that is not (as written by hand or by a broken
// exporter) is normalised with a warning counting the nodes, instead of scaling the node.
// A chain of 30000 nodes, each the child of the one before, crashed the recursive walk (stack
// overflow); each level translates by 1 mm, so the triangle lands 30 m along x.
TEST(GltfImport, AChainOf30000NestedNodesIsWalkedWithoutRecursion) {
  TempDir dir;
  GltfBuilder b;
  const int levels = 30000;
  int node = b.addTriangles("t", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, -1,
                            {{"translation", {0.001, 0, 0}}});
  for (int i = 1; i < levels; ++i) node = b.add("nodes", {{"translation", {0.001, 0, 0}}, {"children", {node}}});
  const Scene s = importGltf(b.write(dir / "chain.gltf").string());
  ASSERT_EQ(s.polygons.size(), 1u);
  const std::vector<Vec3> expected = {{30, 0, 0}, {31, 0, 0}, {30, 1, 0}};
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.polygons[0].vertices[k][c], expected[k][c], 1e-9);
}

TEST(GltfImport, NonUnitRotationsAreNormalisedWithACountedWarning) {
  TempDir dir;
  GltfBuilder b;
  const int positions = b.addPositions(kQuadVertices);  // 2 x 1 m, area 2
  const int indices = b.addIndices({0, 1, 2, 0, 2, 3});
  const double h = std::sqrt(0.5);
  b.addTriangles("a", positions, indices, -1, {{"name", "wall"}, {"rotation", {0, 0, 1, 1}}});  // 90 deg about z
  b.addTriangles("b", positions, indices, -1, {{"name", "floor"}, {"rotation", {0, 0, 2, 2}}, {"translation", {0, 0, 1}}});
  // Within the Khronos validator's tolerance (length 1.005): normalised without a word.
  b.addTriangles("c", positions, indices, -1, {{"rotation", {0, 0, 1.005 * h, 1.005 * h}}, {"translation", {0, 0, 2}}});
  std::vector<std::string> warnings;
  const Scene s = importGltf(b.write(dir / "rotations.gltf").string(), &warnings);
  ASSERT_EQ(s.polygons.size(), 3u);
  for (const Polygon& p : s.polygons) {
    EXPECT_NEAR(polygonArea(p.vertices), 2.0, 1e-12) << p.origin;
    const std::vector<Vec3> turned = {{0, 0, 0}, {0, 2, 0}, {-1, 2, 0}, {-1, 0, 0}};  // (x, y) -> (-y, x)
    for (size_t k = 0; k < turned.size(); ++k) {
      EXPECT_NEAR(p.vertices[k].x, turned[k].x, 1e-12) << p.origin;
      EXPECT_NEAR(p.vertices[k].y, turned[k].y, 1e-12) << p.origin;
    }
  }
  const auto rotation = std::count_if(warnings.begin(), warnings.end(),
                                      [](const std::string& w) { return w.find(": rotation (") != std::string::npos; });
  ASSERT_EQ(rotation, 1) << "one warning for the kind";
  EXPECT_TRUE(mentions(warnings, "node 0 'wall': rotation (0, 0, 1, 1) has length 1.41421, not 1: normalised "
                                 "(glTF 2.0 requires a unit quaternion) (and 1 more like it)"));
}

TEST(GltfImport, MirroringTransformKeepsTheFrontFace) {
  TempDir dir;
  GltfBuilder b;
  b.addTriangles("t", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, -1, {{"scale", {-1, 1, 1}}});
  const Scene s = importGltf(b.write(dir / "mirror.gltf").string());
  ASSERT_EQ(s.polygons.size(), 1u);
  EXPECT_GT(newellNormal(s.polygons[0].vertices).z, 0.0);  // faced +z before the mirror, still does
}

// Two scenes sharing a node: the default one is read; with none named, scene 0 alone (all scenes
// together drew every shared wall twice).
TEST(GltfImport, DefaultSceneElseSceneZero) {
  TempDir dir;
  GltfBuilder b;
  const int a = b.addTriangles("a", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, -1);
  const int c = b.addTriangles("c", b.addPositions({{0, 0, 5}, {1, 0, 5}, {0, 1, 5}}), -1, -1);
  b.doc()["scenes"] = {{{"nodes", {a}}}, {{"nodes", {a, c}}}};
  const Scene first = importGltf(b.write(dir / "first.gltf").string());
  ASSERT_EQ(first.polygons.size(), 1u);
  EXPECT_EQ(first.polygons[0].vertices[0].z, 0.0);
  b.doc()["scene"] = 1;
  const Scene second = importGltf(b.write(dir / "second.gltf").string());
  ASSERT_EQ(second.polygons.size(), 2u);
  EXPECT_EQ(second.polygons[1].vertices[0].z, 5.0);
}

// An exporter's n-gon as a triangle fan, a quad as a strip, and a line (tests/data/repaired/).
TEST(GltfImport, FansAndStripsAreReadLinesSkipped) {
  std::vector<std::string> warnings;
  const Scene s = importGltf(test::dataPath("repaired/gltf_fan_and_strip.gltf").string(), &warnings);
  ASSERT_EQ(s.polygons.size(), 2u);  // each primitive's coplanar triangles merged into one polygon
  std::vector<double> areas;
  for (const Polygon& p : s.polygons) {
    areas.push_back(polygonArea(p.vertices));
    EXPECT_GT(newellNormal(p.vertices).z, 0.0) << "counter-clockwise seen from +z";
  }
  std::sort(areas.begin(), areas.end());
  EXPECT_NEAR(areas[0], 1.0, 1e-6);                       // the strip's unit square
  EXPECT_NEAR(areas[1], 3.0 * std::sqrt(3.0) / 2.0, 1e-6);  // the fan's regular hexagon
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_TRUE(mentions(warnings, "mesh 'exported' primitive 2: mode 1 (points or lines) skipped"));
}

// glTF's doubleSided: the surface receives and reflects on both sides, as two one-sided faces.
TEST(GltfImport, DoubleSidedSurfacesGetABackFaceSetBackAHair) {
  TempDir dir;
  GltfBuilder b;
  b.add("materials", {{"name", "card"}, {"doubleSided", true}});
  b.add("materials", {{"name", "wall"}});
  b.addTriangles("card", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, 0);
  b.addTriangles("wall", b.addPositions({{0, 0, 3}, {0, 1, 3}, {1, 0, 3}}), -1, 1);
  const Scene s = importGltf(b.write(dir / "two-sided.gltf").string());
  ASSERT_EQ(s.polygons.size(), 3u);
  const double diagonal = std::sqrt(1.0 + 1.0 + 9.0);
  int up = 0, down = 0;
  for (const Polygon& p : s.polygons) {
    EXPECT_NEAR(polygonArea(p.vertices), 0.5, 1e-12);
    const Vec3 n = glm::normalize(newellNormal(p.vertices));
    if (p.material == 1) {
      EXPECT_EQ(n.z, -1.0) << "a one-sided wall stays one face";
    } else if (n.z > 0.0) {
      ++up;
      EXPECT_EQ(p.vertices[0].z, 0.0);
    } else {
      ++down;  // the back face, behind the front one as seen from its own side
      for (const Vec3& v : p.vertices) EXPECT_NEAR(v.z, -1e-6 * diagonal, 1e-15);
    }
  }
  EXPECT_EQ(up, 1);
  EXPECT_EQ(down, 1);
}

TEST(GltfImport, AStripOrFanWithoutATriangleIsRefused) {
  TempDir dir;
  GltfBuilder b;
  const int positions = b.addPositions({{0, 0, 0}, {1, 0, 0}});
  b.add("meshes", {{"name", "short"}, {"primitives", {{{"attributes", {{"POSITION", positions}}}, {"mode", 6}}}}});
  b.add("nodes", {{"mesh", 0}});
  try {
    importGltf(b.write(dir / "short.gltf").string());
    ADD_FAILURE() << "a fan of 2 vertices was accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.element(), "mesh 'short' primitive 0");
    EXPECT_NE(std::string(e.what()).find("fewer than one triangle needs"), std::string::npos) << e.what();
  }
}

TEST(GltfImport, MaterialsFromFactorsEmissiveStrengthAndTextureAverage) {
  TempDir dir;
  // A 2 x 1 texture (binary PPM, which the image decoder reads): sRGB (255, 128, 0) and (255, 0, 0).
  {
    std::ofstream ppm(dir / "tex.ppm", std::ios::binary);
    ppm << "P6\n2 1\n255\n";
    ppm.put(char(255)).put(char(128)).put(char(0)).put(char(255)).put(char(0)).put(char(0));
  }
  GltfBuilder b;
  b.add("images", {{"uri", "tex.ppm"}});
  b.add("textures", {{"source", 0}});
  const int textured = b.add("materials", {{"name", "textured"},
                                           {"pbrMetallicRoughness",
                                            {{"baseColorFactor", {0.5, 0.4, 0.2, 1.0}}, {"baseColorTexture", {{"index", 0}}}}}});
  const int lamp = b.add("materials", {{"emissiveFactor", {1.0, 0.5, 0.25}},
                                       {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 40.0}}}}}});
  const int white = b.add("materials", {{"name", "white"}});  // glTF's default baseColorFactor is 1
  const int positions = b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  b.addTriangles("a", positions, -1, textured);
  b.addTriangles("b", positions, -1, lamp, {{"translation", {0, 0, 1}}});
  b.addTriangles("c", positions, -1, white, {{"translation", {0, 0, 2}}});
  std::vector<std::string> warnings;
  const Scene s = importGltf(b.write(dir / "materials.gltf").string(), &warnings);
  ASSERT_EQ(s.materials.size(), 3u);
  // Texture average in linear terms: R (1 + 1)/2, G (srgb(128/255) + 0)/2 with srgb(128/255) =
  // 0.2158605, B 0.
  EXPECT_NEAR(s.materials[0].rho.r, 0.5, 1e-12);
  EXPECT_NEAR(s.materials[0].rho.g, 0.4 * 0.2158605 / 2.0, 1e-7);
  EXPECT_NEAR(s.materials[0].rho.b, 0.0, 1e-12);
  EXPECT_EQ(s.materials[1].name, "material 1");  // generated for the unnamed material
  EXPECT_EQ(s.materials[1].emittance, Rgb(40.0, 20.0, 10.0));
  EXPECT_EQ(s.materials[2].rho, Rgb(0.99));  // a reflectance of 1 cannot converge
  EXPECT_TRUE(mentions(warnings, "material 2 'white': reflectance above 0.99"));
  EXPECT_FALSE(mentions(warnings, "textured"));
  EXPECT_FALSE(mentions(warnings, "emissiveFactor"));
}

// Beyond glTF's [0, 1], read as three.js and the Khronos sample viewer read it, with a warning.
TEST(GltfImport, AnEmissiveFactorAboveOneIsReadAsGivenWithAWarning) {
  TempDir dir;
  GltfBuilder b;
  const int lamp = b.add("materials", {{"name", "lamp"}, {"emissiveFactor", {3.0, 2.0, 1.0}}});
  b.addTriangles("quad", b.addPositions(kQuadVertices), b.addIndices({0, 1, 2, 0, 2, 3}), lamp);
  std::vector<std::string> warnings;
  const Scene s = importGltf(b.write(dir / "bright.gltf").string(), &warnings);
  EXPECT_EQ(s.materials.at(0).emittance, Rgb(3.0, 2.0, 1.0));
  EXPECT_TRUE(mentions(warnings, "material 0 'lamp': emissiveFactor (3, 2, 1) is above glTF's 1, read as given"));
}

// A texture only scales a colour: an image missing or undecodable leaves the factor alone, with
// one counted warning per image (--strict counted three for a missing one).
TEST(GltfImport, UndecodableOrMissingTextureIsWarnedAboutOnceAndTheFactorKept) {
  TempDir dir;
  std::ofstream(dir / "broken.png") << "not an image";
  GltfBuilder b;
  b.add("images", {{"uri", "broken.png"}});
  b.add("images", {{"uri", "absent.png"}});
  b.add("textures", {{"source", 0}});
  b.add("textures", {{"source", 1}});
  for (int t : {0, 1})
    b.add("materials", {{"pbrMetallicRoughness", {{"baseColorFactor", {0.3, 0.2, 0.1, 1}}, {"baseColorTexture", {{"index", t}}}}}});
  const int positions = b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  b.addTriangles("a", positions, -1, 0);
  b.addTriangles("b", positions, -1, 1, {{"translation", {0, 0, 1}}});
  std::vector<std::string> warnings;
  const Scene s = importGltf(b.write(dir / "textures.gltf").string(), &warnings);
  ASSERT_EQ(s.materials.size(), 2u);
  for (const Material& m : s.materials) EXPECT_EQ(m.rho, Rgb(0.3, 0.2, 0.1));
  // One warning per image (tinygltf gave two more for the missing one, the materials one each).
  const std::string path = (dir / "textures.gltf").string();
  const std::string leftOut = ": the textures using it are left out (their materials keep their factors alone)";
  EXPECT_EQ(warnings, (std::vector<std::string>{
                          path + ": image 1: its file '" + (dir / "absent.png").string() + "' does not exist" + leftOut,
                          path + ": image 0 could not be decoded (Unknown image format. STB cannot decode image data "
                                 "for image[0] name = \"\".)" + leftOut}));
}

TEST(GltfImport, ExternalBinBufferBesideTheFile) {
  TempDir dir;
  GltfBuilder b;
  const int lamp = b.add("materials", {{"emissiveFactor", {1, 1, 1}}});
  b.addTriangles("quad", b.addPositions(kQuadVertices), b.addIndices({0, 1, 2, 0, 2, 3}), lamp);
  const Scene s = importGltf(b.write(dir / "external.gltf", "external.bin").string());
  ASSERT_EQ(s.polygons.size(), 1u);
  EXPECT_EQ(s.polygons[0].vertices, kQuadVertices);
}

// In a glTF URI (RFC 3986) a '+' is a '+', as other glTF readers take it; tinygltf alone would
// read a space, here the decoy beside it.
TEST(GltfImport, APlusInABufferUriNamesAPlusNotASpace) {
  TempDir dir;
  GltfBuilder b;
  const int lamp = b.add("materials", {{"emissiveFactor", {1, 1, 1}}});
  b.addTriangles("quad", b.addPositions(kQuadVertices), b.addIndices({0, 1, 2, 0, 2, 3}), lamp);
  const std::filesystem::path gltf = b.write(dir / "plus.gltf", "lamp+shade.bin");
  const auto bytes = std::filesystem::file_size(dir / "lamp+shade.bin");
  std::ofstream(dir / "lamp shade.bin", std::ios::binary) << std::string(bytes, '\0');
  const Scene s = importGltf(gltf.string());
  ASSERT_EQ(s.polygons.size(), 1u);
  EXPECT_EQ(s.polygons[0].vertices, kQuadVertices);
  // "%2B" is a '+' too.
  nlohmann::json doc = nlohmann::json::parse(std::ifstream(gltf));
  doc["buffers"][0]["uri"] = "lamp%2Bshade.bin";
  std::ofstream(dir / "escaped.gltf") << doc.dump();
  EXPECT_EQ(importGltf((dir / "escaped.gltf").string()).polygons.at(0).vertices, kQuadVertices);
}

TEST(GltfImport, GlbWrittenByTheBakeExportReadsBack) {
  TempDir dir;
  DisplayMesh mesh;
  mesh.positions = kQuadVertices;
  mesh.normals.assign(4, Vec3(0, 0, 1));
  mesh.indices = {0, 1, 2, 0, 2, 3};
  const std::string path = (dir / "bake.glb").string();
  writeBakeGlb(path, mesh, std::vector<Rgb>(4, Rgb(1.0)), /*sceneUpAxis=*/1);
  std::vector<std::string> warnings;
  const Scene s = importGltf(path, &warnings);
  ASSERT_EQ(s.polygons.size(), 1u);
  EXPECT_EQ(s.polygons[0].vertices, kQuadVertices);
}

}  // namespace
}  // namespace radmesh
