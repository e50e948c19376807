// Each file under tests/data/bad/gltf_* is refused with a SceneError naming the file, the element
// at fault and (where tinygltf refused it) tinygltf's own message.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <functional>
#include <future>
#include <memory>
#include <string>
#include <thread>

#include "solver/io/gltf_import.h"
#include "solver/scene/scene_error.h"
#include "tests/solver/io/gltf_test_file.h"
#include "tests/test_paths.h"

namespace radmesh {
namespace {

struct GltfRefusal {
  std::string element;
  std::string what;  // the message includes this
};

GltfRefusal gltfRefusalAt(const std::string& path) {
  try {
    importGltf(path);
  } catch (const SceneError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("(fix: "), std::string::npos) << e.what();
    return {e.element(), e.what()};
  }
  ADD_FAILURE() << path << " was accepted";
  return {};
}

GltfRefusal gltfRefusal(const std::string& name) { return gltfRefusalAt(test::dataPath("bad/" + name).string()); }

TEST(GltfBadInput, TruncatedJsonNamesTheJsonAndKeepsTinygltfsMessage) {
  const GltfRefusal r = gltfRefusal("gltf_truncated.gltf");
  EXPECT_EQ(r.element, "JSON");
  EXPECT_NE(r.what.find("tinygltf: "), std::string::npos) << r.what;
  EXPECT_NE(r.what.find("parse error"), std::string::npos) << r.what;  // the JSON parser's words
}

TEST(GltfBadInput, TruncatedGlbNamesTheContainer) {
  const GltfRefusal r = gltfRefusal("gltf_truncated.glb");
  EXPECT_EQ(r.element, "GLB container");
  EXPECT_NE(r.what.find("492 bytes, its header declares 512"), std::string::npos) << r.what;
}

// The header's total is right, its JSON chunk's length is not: the message names that length.
TEST(GltfBadInput, AGlbJsonChunkLongerThanTheFileNamesTheChunk) {
  test::TempDir dir;
  const std::string json = R"({"asset":{"version":"2.0"}})";
  std::string glb = "glTF";
  const auto word = [&](uint32_t v) {
    for (int k = 0; k < 4; ++k) glb += static_cast<char>(v >> (8 * k) & 0xFF);
  };
  word(2);
  word(static_cast<uint32_t>(20 + json.size()));
  word(0xFFFFFFF0u);  // the JSON chunk's length
  word(0x4E4F534Au);  // "JSON"
  glb += json;
  const std::string path = (dir / "chunk.glb").string();
  std::ofstream(path, std::ios::binary) << glb;
  const GltfRefusal r = gltfRefusalAt(path);
  EXPECT_EQ(r.element, "GLB container");
  EXPECT_NE(r.what.find(fmt::format("its JSON chunk declares 4294967280 bytes, but {} follow the chunk's header", json.size())),
            std::string::npos)
      << r.what;
}

TEST(GltfBadInput, MissingExternalBufferNamesTheBuffer) {
  const GltfRefusal r = gltfRefusal("gltf_missing_buffer.gltf");
  EXPECT_EQ(r.element, "buffer 0");
  EXPECT_NE(r.what.find("gltf_missing_buffer.bin' does not exist"), std::string::npos) << r.what;
}

// An embedded buffer shorter than its byteLength: tinygltf quotes the whole data: URI (megabytes
// in a real model); the message names the buffer and the two lengths, and stays short.
TEST(GltfBadInput, ADataUriShorterThanItsByteLengthNamesTheBufferBriefly) {
  test::TempDir dir;
  test::GltfBuilder gltf;
  std::vector<Vec3> points(3000);
  for (size_t i = 0; i < points.size(); ++i) points[i] = {static_cast<double>(i), 0.0, static_cast<double>(i % 2)};
  gltf.addTriangles("strip", gltf.addPositions(points), gltf.addIndices({0, 1, 2}), -1);
  const std::string path = gltf.write(dir / "short.gltf").string();
  nlohmann::json doc = nlohmann::json::parse(std::ifstream(path));
  const uint64_t held = doc["buffers"][0]["byteLength"].get<uint64_t>();
  doc["buffers"][0]["byteLength"] = held + 4;
  std::ofstream(path) << doc.dump();
  const GltfRefusal r = gltfRefusalAt(path);
  EXPECT_EQ(r.element, "buffer 0");
  EXPECT_NE(r.what.find(fmt::format("its data: URI holds {} bytes, fewer than its byteLength, {}", held, held + 4)),
            std::string::npos)
      << r.what;
  EXPECT_LT(r.what.size(), 1000u);
}

TEST(GltfBadInput, IndexOutOfRangeNamesTheMeshPrimitive) {
  const GltfRefusal r = gltfRefusal("gltf_bad_index.gltf");
  EXPECT_EQ(r.element, "mesh 'bad' primitive 0");
  EXPECT_NE(r.what.find("index 2 is 7, out of range for its 3 positions"), std::string::npos) << r.what;
}

TEST(GltfBadInput, NaNPositionNamesTheAccessorAndItsUser) {
  const GltfRefusal r = gltfRefusal("gltf_nan.gltf");
  EXPECT_EQ(r.element, "accessor 0 (POSITION of mesh 'nan' primitive 0)");
  EXPECT_NE(r.what.find("element 1 has a NaN"), std::string::npos) << r.what;
}

TEST(GltfBadInput, AccessorReadingPastItsBufferViewNamesTheAccessor) {
  const GltfRefusal r = gltfRefusal("gltf_accessor_range.gltf");
  EXPECT_EQ(r.element, "accessor 0 (POSITION of mesh 'short' primitive 0)");
  EXPECT_NE(r.what.find("reads 10 elements from byte 0 of bufferView 0, which holds only 36 bytes"), std::string::npos)
      << r.what;
}

TEST(GltfBadInput, NegativeEmissionNamesTheMaterial) {
  const GltfRefusal r = gltfRefusal("gltf_negative_emission.gltf");
  EXPECT_EQ(r.element, "material 0 'lamp'");
  EXPECT_NE(r.what.find("negative"), std::string::npos) << r.what;
}

// Each factor is checked, not only their product: -1 x -1 must not become an emitter.
TEST(GltfBadInput, NegativeEmissiveFactorTimesNegativeStrengthNamesEachFactor) {
  test::TempDir dir;
  const auto refusal = [&](const nlohmann::json& factor, double strength) {
    test::GltfBuilder b;
    const int lamp = b.add("materials", {{"name", "lamp"},
                                         {"emissiveFactor", factor},
                                         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", strength}}}}}});
    b.addTriangles("t", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, lamp);
    return gltfRefusalAt(b.write(dir / "lamp.gltf").string());
  };
  const GltfRefusal both = refusal({-1, -1, -1}, -1.0);
  EXPECT_EQ(both.element, "material 0 'lamp'");
  EXPECT_NE(both.what.find("emissiveFactor -1 is negative"), std::string::npos) << both.what;
  const GltfRefusal strength = refusal({1, 1, 1}, -1.0);
  EXPECT_NE(strength.what.find("emissiveStrength -1 is negative"), std::string::npos) << strength.what;
}

// glTF's default white (1, 1, 1) is lowered to the largest reflectance with a warning; a factor
// outside [0, 1] breaks the format itself.
TEST(GltfBadInput, BaseColorAboveOneNamesTheMaterial) {
  const GltfRefusal r = gltfRefusal("gltf_rho_above_one.gltf");
  EXPECT_EQ(r.element, "material 0 'too_bright'");
  EXPECT_NE(r.what.find("baseColorFactor 1.5 is outside [0, 1]"), std::string::npos) << r.what;
}

TEST(GltfBadInput, NodeCycleNamesTheNode) {
  const GltfRefusal r = gltfRefusal("gltf_node_cycle.gltf");
  EXPECT_EQ(r.element, "node 0 'a'");
  EXPECT_NE(r.what.find("cycle"), std::string::npos) << r.what;
}

// Imported on a thread of its own, so that a hang fails the test instead of stalling the run.
GltfRefusal gltfRefusalWithin(std::chrono::seconds limit, const std::string& path) {
  auto task = std::make_shared<std::packaged_task<GltfRefusal()>>([path] { return gltfRefusalAt(path); });
  std::future<GltfRefusal> refusal = task->get_future();
  std::thread([task] { (*task)(); }).detach();
  if (refusal.wait_for(limit) == std::future_status::timeout) {
    ADD_FAILURE() << path << " still importing after " << limit.count() << " s";
    return {};
  }
  return refusal.get();
}

// glTF 2.0 allows a node one parent. A node shared by two parents is refused by name; so is a
// chain of 40 nodes each listed twice as the next one's child, which a traversal would walk 2^40
// times, before any traversal.
TEST(GltfBadInput, ANodeWithTwoParentsIsRefusedBeforeTraversal) {
  test::TempDir dir;
  test::GltfBuilder shared;
  const int mesh = shared.addTriangles("t", shared.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, -1,
                                       {{"name", "shared"}});
  shared.add("nodes", {{"name", "left"}, {"children", {mesh}}});
  shared.add("nodes", {{"name", "right"}, {"children", {mesh}}});
  const GltfRefusal two = gltfRefusalAt(shared.write(dir / "two_parents.gltf").string());
  EXPECT_EQ(two.element, "node 0 'shared'");
  EXPECT_NE(two.what.find("is a child of both node 1 'left' and node 2 'right'; glTF 2.0 (3.5.2) allows a node at "
                          "most one parent"),
            std::string::npos)
      << two.what;

  test::GltfBuilder chain;
  const int levels = 40;
  for (int i = 0; i < levels; ++i)
    chain.add("nodes", {{"name", fmt::format("L{}", i)}, {"children", {i + 1, i + 1}}});
  chain.addTriangles("t", chain.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, -1,
                     {{"name", fmt::format("L{}", levels)}});
  const GltfRefusal twice = gltfRefusalWithin(std::chrono::seconds(20), chain.write(dir / "chain.gltf").string());
  EXPECT_EQ(twice.element, "node 1 'L1'");
  EXPECT_NE(twice.what.find("is listed twice among the children of node 0 'L0'"), std::string::npos) << twice.what;
}

// A scene's nodes are distinct roots: a node (a wall, a light) listed twice, or a root that is also
// another node's child, was drawn twice, doubling its area or its light.
TEST(GltfBadInput, ASceneNodeListedTwiceOrAlsoAChildIsRefused) {
  test::TempDir dir;
  const auto refusal = [&](const std::string& name, const nlohmann::json& sceneNodes, bool grouped = false) {
    test::GltfBuilder b;
    b.addTriangles("t", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, -1, {{"name", "wall"}});
    b.add("nodes", {{"name", "lamp"}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    b.add("nodes", {{"name", "group"}, {"children", grouped ? nlohmann::json{0} : nlohmann::json::array()}});
    b.doc()["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"intensity", 10}}};
    b.doc()["scenes"] = {{{"nodes", sceneNodes}}};
    return gltfRefusalAt(b.write(dir / name).string());
  };
  const std::string fix = " (it would be drawn twice) (fix: list each root node once in the scene's nodes, and no "
                          "node's child (it comes with its parent))";
  const std::string rule = "; glTF 2.0 (3.5.2) lists each root node of a scene once, and only root nodes";
  const GltfRefusal wall = refusal("wall.gltf", {0, 1, 0});
  EXPECT_EQ(wall.what, (dir / "wall.gltf").string() + ": node 0 'wall': is listed twice among the nodes of scene 0" +
                           rule + fix);
  const GltfRefusal lamp = refusal("lamp.gltf", {0, 1, 1});
  EXPECT_EQ(lamp.what, (dir / "lamp.gltf").string() + ": node 1 'lamp': is listed twice among the nodes of scene 0" +
                           rule + fix);
  const GltfRefusal child = refusal("child.gltf", {0, 2}, true);
  EXPECT_EQ(child.what, (dir / "child.gltf").string() +
                            ": node 0 'wall': is among the nodes of scene 0 and a child of node 2 'group'" + rule + fix);
}

// A node scale of 1e39 put inf in the bake's float positions, and 1e155 overflowed the area into
// "degenerate triangles dropped": past MGF's bound, 1e30 m, a world-space vertex is refused.
TEST(GltfBadInput, AVertexPastTheCoordinateBoundNamesTheMeshAndNode) {
  test::TempDir dir;
  for (const double scale : {1e39, 1e155}) {
    test::GltfBuilder b;
    const int inner = b.addTriangles("t", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, -1, {{"name", "wall"}});
    b.add("nodes", {{"name", "huge"}, {"scale", {scale, scale, scale}}, {"children", {inner}}});
    const std::string path = b.write(dir / "huge.gltf").string();
    const GltfRefusal r = gltfRefusalAt(path);
    EXPECT_EQ(r.what, path + fmt::format(": mesh 't' primitive 0 (node 0 'wall'): vertex 1 lands at ({:g}, 0, 0) "
                                         "through the node transforms, farther than 1e+30 m from the origin, where "
                                         "lengths and areas overflow (fix: check the scales and translations of the "
                                         "node and its parents (glTF is in metres))",
                                         scale));
  }
}

// A required extension radmesh does not implement loaded as nothing (meshopt) or failed as "no
// valid bufferView" (Draco); the extensions it reads may still be required.
TEST(GltfBadInput, ARequiredExtensionRadmeshDoesNotImplementIsRefusedByName) {
  test::TempDir dir;
  const auto write = [&](const std::string& name, const nlohmann::json& required) {
    test::GltfBuilder b;
    const int lamp = b.add("materials", {{"emissiveFactor", {1, 1, 1}}});
    b.addTriangles("t", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, lamp);
    b.doc()["extensionsUsed"] = required;
    b.doc()["extensionsRequired"] = required;
    return b.write(dir / name).string();
  };
  const std::string reads = "(it accepts KHR_lights_punctual, KHR_materials_emissive_strength, KHR_materials_unlit, "
                            "KHR_texture_transform, KHR_mesh_quantization)";
  for (const std::string extension : {"EXT_meshopt_compression", "KHR_draco_mesh_compression"}) {
    const std::string path = write(extension + ".gltf", {"KHR_lights_punctual", extension});
    EXPECT_EQ(gltfRefusalAt(path).what, path + ": extensionsRequired: the file requires " + extension +
                                            ", which radmesh does not implement " + reads +
                                            " (fix: export the file without Draco or meshopt compression)");
  }
  const std::string other = write("other.gltf", {"KHR_materials_variants"});
  EXPECT_EQ(gltfRefusalAt(other).what, other + ": extensionsRequired: the file requires KHR_materials_variants, which "
                                               "radmesh does not implement " + reads +
                                               " (fix: export the file without KHR_materials_variants)");
  EXPECT_EQ(importGltf(write("read.gltf", {"KHR_lights_punctual", "KHR_materials_emissive_strength",
                                           "KHR_texture_transform"}))
                .polygons.size(),
            1u);
}

// tinygltf's own words leaked: "File not found : /etc/passwd", "File size mismatch", a whole data:
// URI, a PNG's '\x89' as a JSON error, "Perspective camera description not found.". Each is now
// said in radmesh's words, naming the element.
TEST(GltfBadInput, BufferUriPngAndCameraProblemsAreSaidInRadmeshsWords) {
  test::TempDir dir;
  const auto write = [&](const std::string& name, const std::function<void(nlohmann::json&)>& change) {
    test::GltfBuilder b;
    b.addTriangles("t", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, -1);
    const std::string path = b.write(dir / name, "mesh.bin").string();
    nlohmann::json doc = nlohmann::json::parse(std::ifstream(path));
    change(doc);
    std::ofstream(path) << doc.dump();
    return path;
  };
  const std::string absolute = write("absolute.gltf", [](nlohmann::json& d) { d["buffers"][0]["uri"] = "/etc/passwd"; });
  EXPECT_EQ(gltfRefusalAt(absolute).what,
            absolute + ": buffer 0: its uri '/etc/passwd' is absolute; glTF names external files relative to the glTF "
                       "file (fix: copy the file beside the glTF file (or below it) and give its relative path)");
  const std::string longer = write("longer.gltf", [&](nlohmann::json&) {
    std::ofstream(dir / "mesh.bin", std::ios::binary | std::ios::app) << std::string(376, '\0');
  });
  EXPECT_EQ(gltfRefusalAt(longer).what,
            longer + ": buffer 0: its file '" + (dir / "mesh.bin").string() +
                "' has 412 bytes, but its byteLength is 36 (the buffer's length, which tinygltf requires the file to "
                "match) (fix: set byteLength to the file's size, or export the file again)");
  const std::string plain = write("plain.gltf", [](nlohmann::json& d) {
    d["buffers"][0]["uri"] = "data:application/octet-stream," + std::string(5000, 'A');
  });
  EXPECT_EQ(gltfRefusalAt(plain).what,
            plain + ": buffer 0: its data: URI ('data:application/octet-stream,AAAAAAAAAA...') is not base64 of a type "
                    "glTF embeds (fix: embed the buffer as data:application/octet-stream;base64,... (or "
                    "data:image/png;base64,... for a PNG))");
  const std::string camera = write("camera.gltf", [](nlohmann::json& d) { d["cameras"] = {{{"type", "perspective"}}}; });
  EXPECT_EQ(gltfRefusalAt(camera).what,
            camera + ": camera 0: could not be loaded (tinygltf: Perspective camera description not found.): it is "
                     "incomplete (a \"perspective\" camera needs its \"perspective\" object; radmesh uses no cameras) "
                     "(fix: give it its \"perspective\" or \"orthographic\" object, or delete the camera)");
  const std::string png = (dir / "picture.glb").string();
  std::ofstream(png, std::ios::binary) << std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16) << std::string(40, '\0');
  EXPECT_EQ(gltfRefusalAt(png).what, png + ": GLB container: is not a GLB: it does not start with 'glTF' (fix: give a "
                                           "glTF binary (.glb) or a .gltf text file; check what the file really is)");
}

// glTF 1.0, a different format, loaded silently as 2.0: asset.version "1.0" and a GLB header of
// version 1 are refused; "2.1" (a later minor version) still loads.
TEST(GltfBadInput, GltfOneIsRefusedByItsVersion) {
  test::TempDir dir;
  test::GltfBuilder b;
  b.addTriangles("t", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, -1);
  const std::string glb = (dir / "old.glb").string();
  std::ofstream(glb, std::ios::binary) << test::glbContainer(b.doc().dump(), 1);
  EXPECT_EQ(gltfRefusalAt(glb).what, glb + ": GLB container: its header says version 1, not 2: glTF 1.0's binary "
                                           "format, which radmesh does not read (fix: re-export the model as glTF 2.0)");
  b.doc()["asset"]["version"] = "1.0";
  const std::string gltf = b.write(dir / "old.gltf").string();
  EXPECT_EQ(gltfRefusalAt(gltf).what, gltf + ": asset: its version is '1.0', not glTF 2.0 (glTF 1.0 is a different "
                                             "format) (fix: re-export the model as glTF 2.0)");
  // A version that is no glTF's is not told it is glTF 1.0.
  b.doc()["asset"]["version"] = "null";
  const std::string odd = b.write(dir / "odd.gltf").string();
  EXPECT_EQ(gltfRefusalAt(odd).what, odd + ": asset: its version is 'null', not glTF 2.0 (fix: re-export the model as "
                                           "glTF 2.0)");
  b.doc()["asset"]["version"] = "2.1";
  EXPECT_EQ(importGltf(b.write(dir / "minor.gltf").string()).polygons.size(), 1u);
}

// A rotation that is no rotation at all cannot be normalised (GltfImport.* checks the repair).
TEST(GltfBadInput, AZeroRotationNamesTheNode) {
  test::TempDir dir;
  test::GltfBuilder b;
  b.addTriangles("t", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, -1,
                 {{"name", "wall"}, {"rotation", {0, 0, 0, 0}}});
  const GltfRefusal r = gltfRefusalAt(b.write(dir / "zero.gltf").string());
  EXPECT_EQ(r.element, "node 0 'wall'");
  EXPECT_NE(r.what.find("rotation (0, 0, 0, 0) is zero or not finite"), std::string::npos) << r.what;
}

// Its last row was dropped unread: the quad moved without a word.
TEST(GltfBadInput, AProjectiveNodeMatrixNamesTheNode) {
  test::TempDir dir;
  test::GltfBuilder b;
  b.addTriangles("t", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, -1,
                 {{"name", "wall"}, {"matrix", {1, 0, 0, 0.5, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}});
  const GltfRefusal r = gltfRefusalAt(b.write(dir / "projective.gltf").string());
  EXPECT_EQ(r.element, "node 0 'wall'");
  EXPECT_NE(r.what.find("its matrix's last row is (0.5, 0, 0, 1), not (0, 0, 0, 1)"), std::string::npos) << r.what;
}

// 20000 nested '[' overflowed the stack in the JSON parser (exit 139): refused before parsing, in
// a .gltf and in a .glb's JSON chunk alike.
TEST(GltfBadInput, JsonNestedTooDeeplyIsRefusedBeforeParsing) {
  test::TempDir dir;
  test::GltfBuilder b;
  b.addTriangles("t", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, -1);
  const std::string gltf = b.write(dir / "deep.gltf").string();
  std::string json = nlohmann::json::parse(std::ifstream(gltf)).dump();
  json.pop_back();
  json += R"(,"extras":{"note":"[[ quoted \" brackets do not count","deep":)" + std::string(20000, '[') +
          std::string(20000, ']') + "}}";
  std::ofstream(gltf) << json;
  const std::string glb = (dir / "deep.glb").string();
  std::ofstream(glb, std::ios::binary) << test::glbContainer(json);
  for (const std::string& path : {gltf, glb}) {
    const GltfRefusal r = gltfRefusalAt(path);
    EXPECT_EQ(r.what, path + ": JSON: nests arrays and objects more than 512 levels deep, which no glTF needs (parsing "
                             "it would overflow the stack) (fix: remove the deep nesting (look in \"extras\") or "
                             "export the file again)");
  }
}

// 512 levels (the document's object, "extras" and 510 arrays in it), the most radmesh reads, load.
TEST(GltfBadInput, JsonNestedTo512LevelsLoads) {
  test::TempDir dir;
  test::GltfBuilder b;
  b.addTriangles("t", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, -1);
  b.doc()["extras"] = nlohmann::json::array();
  nlohmann::json* inner = &b.doc()["extras"];
  for (int level = 3; level <= 512; ++level) {
    inner->push_back(nlohmann::json::array());
    inner = &inner->back();
  }
  EXPECT_EQ(importGltf(b.write(dir / "nested.gltf").string()).polygons.size(), 1u);
}

// A buffer or image whose URI names a FIFO blocked the reader for ever; one naming a folder gave
// "std::bad_alloc ... does not exist". Both are refused before tinygltf opens them, as MGF's
// include and ies are.
TEST(GltfBadInput, AUriNamingAFifoOrAFolderIsRefusedWithoutBlocking) {
  test::TempDir dir;
  const std::string fifo = (dir / "fifo.bin").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto refusal = [&](const std::string& name, const std::string& bufferUri, const std::string& imageUri) {
    test::GltfBuilder b;
    b.addTriangles("t", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, -1);
    if (!imageUri.empty()) b.add("images", {{"uri", imageUri}});
    const std::string path = b.write(dir / name, "mesh.bin").string();
    nlohmann::json doc = nlohmann::json::parse(std::ifstream(path));
    doc["buffers"][0]["uri"] = bufferUri;
    std::ofstream(path) << doc.dump();
    const GltfRefusal r = gltfRefusalWithin(std::chrono::seconds(10), path);
    if (r.what.empty()) ::close(::open(fifo.c_str(), O_WRONLY | O_NONBLOCK));  // let a blocked reader go
    return std::pair{path, r};
  };
  const std::string fifoFile = (dir.path() / "fifo.bin").string();
  const auto [buffer, fromBuffer] = refusal("buffer.gltf", "fifo.bin", "");
  EXPECT_EQ(fromBuffer.what, buffer + ": buffer 0: its uri 'fifo.bin' names '" + fifoFile +
                                 "', which is a FIFO, socket or device, not a file (fix: give the uri of the buffer's "
                                 "file, beside the glTF file, or embed the buffer)");
  const auto [image, fromImage] = refusal("image.gltf", "mesh.bin", "fifo%2Ebin");
  EXPECT_EQ(fromImage.what, image + ": image 0: its uri 'fifo%2Ebin' names '" + fifoFile +
                                "', which is a FIFO, socket or device, not a file (fix: give the uri of the image's "
                                "file, beside the glTF file, or embed the image)");
  const auto [folder, fromFolder] = refusal("folder.gltf", ".", "");
  EXPECT_EQ(fromFolder.what, folder + ": buffer 0: its uri '.' names '" + (dir.path() / ".").string() +
                                 "', which is a folder, not a file (fix: give the uri of the buffer's file, beside the "
                                 "glTF file, or embed the buffer)");
}

TEST(GltfBadInput, MissingFileIsAClearError) {
  const GltfRefusal r = gltfRefusal("gltf_no_such_file.gltf");
  EXPECT_NE(r.what.find("does not exist"), std::string::npos) << r.what;
}

}  // namespace
}  // namespace radmesh
