#include "solver/io/builtin_scenes.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <future>
#include <map>
#include <string>
#include <utility>

#include "solver/bake/bake_reader.h"
#include "solver/io/builtin_building.h"
#include "solver/meshing/meshing.h"
#include "solver/io/scene_builder.h"
#include "solver/scene/scene_error.h"
#include "solver/io/scene_loader.h"
#include "tests/solver/io/gltf_test_file.h"  // TempDir
#include "tests/solver/meshing/mesh_checks.h"
#include "tests/test_paths.h"

namespace radmesh {
namespace {

using test::signedVolume;

int emitterCount(const Scene& s) {
  int n = 0;
  for (const Polygon& p : s.polygons) n += s.materials[p.material].emits() ? 1 : 0;
  return n;
}

double polygonAreaSum(const Scene& s) {
  double a = 0.0;
  for (const Polygon& p : s.polygons) a += polygonArea(p.vertices);
  return a;
}

std::vector<Polygon> polygonsFrom(const Scene& s, const std::string& originPrefix) {
  std::vector<Polygon> out;
  for (const Polygon& p : s.polygons)
    if (p.origin.rfind(originPrefix, 0) == 0) out.push_back(p);
  return out;
}

TEST(BuiltinScenes, EveryOneValidatesAndMeshesKeepingArea) {
  for (const std::string& name : builtinSceneNames()) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(isBuiltinScene(name));
    const Scene s = builtinScene(name);
    EXPECT_NO_THROW(validateScene(s));
    const auto patches = meshScene(s);
    test::expectValidPatches(patches, kDefaultCellM, name, s);
    test::expectAreaKept(s, patches, 1e-9, name);
  }
}

// The paper's "Sitterson 365 office" had 3959 patches at the 15-inch grid (section 1.6).
TEST(BuiltinScenes, OfficeIsCloseToThePapersOffice) {
  const Scene s = builtinScene("office");
  EXPECT_EQ(s.polygons.size(), 1246u);
  EXPECT_EQ(meshScene(s).size(), 3932u);  // its round table's facets on grids of their own
  EXPECT_EQ(emitterCount(s), 6);
  EXPECT_NEAR(emittedPowerW(s), 6 * 1.2 * 0.6 * (10.0 + 9.6 + 8.8), 1e-9);
  EXPECT_NEAR(polygonAreaSum(s), 247.85990895, 1e-6);
}

TEST(BuiltinScenes, OfficeShellIsClosedAndFacesIn) {
  const Scene s = builtinScene("office");
  // The room, its door recess (0.9 x 2.1 x 0.15) and two window recesses (1.5 x 1.3 x 0.3),
  // all seen from inside: negative volume.
  const double volume = 7.2 * 5.4 * 2.7 + 0.9 * 2.1 * 0.15 + 2 * 1.5 * 1.3 * 0.3;
  EXPECT_NEAR(signedVolume(polygonsFrom(s, "room 'office'")), -volume, 1e-9);
  // Nothing below the floor or above the ceiling; the recesses are the only things outside.
  for (const Polygon& p : s.polygons)
    for (const Vec3& v : p.vertices) {
      EXPECT_GE(v.z, 0.0) << p.origin;
      EXPECT_LE(v.z, 2.7) << p.origin;
      EXPECT_TRUE(p.origin.find("opening") != std::string::npos ||
                  (v.x >= 0 && v.x <= 7.2 && v.y >= 0 && v.y <= 5.4))
          << p.origin;
    }
}

// Separating axis test on two convex polygons in a plane's 2D projection: do they share area?
bool overlapInArea(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  for (const auto* poly : {&a, &b})
    for (size_t i = 0; i < poly->size(); ++i) {
      const Vec2 e = (*poly)[(i + 1) % poly->size()] - (*poly)[i];
      const Vec2 axis{-e.y, e.x};
      double loA = 1e300, hiA = -1e300, loB = 1e300, hiB = -1e300;
      for (const Vec2& p : a) loA = std::min(loA, glm::dot(p, axis)), hiA = std::max(hiA, glm::dot(p, axis));
      for (const Vec2& p : b) loB = std::min(loB, glm::dot(p, axis)), hiB = std::max(hiB, glm::dot(p, axis));
      const double eps = 1e-9 * glm::length(axis);
      if (hiA <= loB + eps || hiB <= loA + eps) return false;
    }
  return true;
}

// No two patches (of either facing) share area in one plane: coplanar overlap would make the
// item buffer's depth test a coin toss.
TEST(BuiltinScenes, OfficeHasNoCoplanarOverlap) {
  const Scene s = builtinScene("office");
  const auto patches = meshScene(s);
  std::map<std::array<long long, 4>, std::vector<int>> planes;  // unsigned plane -> patches
  for (size_t i = 0; i < patches.size(); ++i) {
    Vec3 n = patches[i].normal;
    if (n[test::dominantAxis(n)] < 0) n = -n;
    const double d = glm::dot(n, patches[i].centroid);
    planes[{std::llround(n.x * 1e6), std::llround(n.y * 1e6), std::llround(n.z * 1e6), std::llround(d * 1e6)}]
        .push_back(static_cast<int>(i));
  }
  int pairs = 0;
  for (const auto& [key, members] : planes) {
    const int drop = test::dominantAxis(patches[members[0]].normal);
    const auto flat = [&](int i) {
      std::vector<Vec2> out;
      for (int k = 0; k < patches[i].vertexCount; ++k)
        out.push_back({patches[i].vertices[k][(drop + 1) % 3], patches[i].vertices[k][(drop + 2) % 3]});
      return out;
    };
    for (size_t a = 0; a < members.size(); ++a)
      for (size_t b = a + 1; b < members.size(); ++b) {
        ++pairs;
        ASSERT_FALSE(overlapInArea(flat(members[a]), flat(members[b])))
            << s.polygons[patches[members[a]].polygon].origin << " overlaps "
            << s.polygons[patches[members[b]].polygon].origin;
      }
  }
  EXPECT_GT(pairs, 10000);  // the floor alone has hundreds of coplanar patches
}

TEST(BuiltinScenes, FurnaceIsAClosedUniformBox) {
  const Scene s = builtinScene("furnace");
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].rho, Rgb(0.5));
  EXPECT_EQ(s.materials[0].emittance, Rgb(1.0));
  EXPECT_EQ(s.polygons.size(), 6u);
  EXPECT_NEAR(signedVolume(s.polygons), -1.0, 1e-12);
  // Each face: columns 0 .. 0.381 .. 0.762 .. 1 and as many rows.
  EXPECT_EQ(meshScene(s).size(), 54u);
  EXPECT_NEAR(emittedPowerW(s), 6 * 3.0, 1e-12);
}

TEST(BuiltinScenes, TwoRoomsJoinedByADoorWithOneLight) {
  const Scene s = builtinScene("two-rooms");
  EXPECT_EQ(s.polygons.size(), 24u);
  EXPECT_EQ(meshScene(s).size(), 1262u);
  EXPECT_EQ(emitterCount(s), 1);
  // Both rooms and the passage through the 0.2 m wall, from inside: one closed surface.
  EXPECT_NEAR(signedVolume(s.polygons), -(2 * 4 * 4 * 2.7 + 0.2 * 0.9 * 2.1), 1e-9);
  for (const Polygon& p : s.polygons) {
    if (!s.materials[p.material].emits()) continue;
    for (const Vec3& v : p.vertices) EXPECT_LT(v.x, 4.0) << "the light belongs in the first room";
  }
}

// building:COLSxROWS: three lights a room, one a room width in each corridor, one per wing in the
// spine; every door 0.9 m x 2.1 m; a size it cannot make refused naming the form.
TEST(BuiltinScenes, BuildingHasTheLayoutsLightsAndDoors) {
  for (const std::string name : {"building:1x1", "building:2x3", "building:3x2"}) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(isBuiltinScene(name));
    const Scene s = builtinScene(name);
    EXPECT_NO_THROW(validateScene(s));
    const BuildingLayout layout = parseBuildingName(name);
    const int lights = 3 * layout.rooms() + layout.wings() * layout.cols + layout.wings();
    EXPECT_EQ(emitterCount(s), lights);
    EXPECT_NEAR(emittedPowerW(s), lights * 1.2 * 0.6 * (10.0 + 9.6 + 8.8), 1e-9);
    EXPECT_EQ(s.source, name);
  }
  EXPECT_EQ(builtinScene("building:1x1").polygons.size(), 236u);
  EXPECT_EQ(meshScene(builtinScene("building:1x1")).size(), 3735u);
  EXPECT_EQ(parseBuildingName("building:10x10").doors(), 105);
  for (const std::string bad : {"building:", "building:0x3", "building:3", "building:3x", "building:101x1",
                                "building:2x2x2", "building:-1x2"}) {
    SCOPED_TRACE(bad);
    EXPECT_TRUE(isBuiltinScene(bad));
    try {
      builtinScene(bad);
      ADD_FAILURE() << "accepted";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("building:COLSxROWS"), std::string::npos) << e.what();
    }
  }
}

TEST(BuiltinScenes, UnknownNameListsTheKnownOnes) {
  try {
    builtinScene("ofice");
    ADD_FAILURE() << "accepted an unknown name";
  } catch (const SceneError& e) {
    const std::string message = e.what();
    for (const std::string& name : builtinSceneNames())
      EXPECT_NE(message.find(name), std::string::npos) << message;
    EXPECT_NE(message.find("building:COLSxROWS"), std::string::npos) << message;
  }
  EXPECT_FALSE(isBuiltinScene("ofice"));
}

TEST(SceneBuilder, BoxesFaceOutRoomsFaceIn) {
  SceneBuilder b("test");
  const int m = b.addMaterial("m", Rgb(0.5), Rgb(1.0));
  b.addBox({1, 2, 3}, {1.5, 3, 3.25}, m, "box");
  Scene box = b.take();
  EXPECT_EQ(box.polygons.size(), 6u);
  EXPECT_NEAR(signedVolume(box.polygons), 0.5 * 1 * 0.25, 1e-12);

  SceneBuilder l("test");
  l.addMaterial("m", Rgb(0.5), Rgb(1.0));
  l.addPrism({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 0.5, 1.0, m, "L");  // 3 m^2 footprint
  EXPECT_NEAR(signedVolume(l.take().polygons), 1.5, 1e-12);

  SceneBuilder r("test");
  r.addMaterial("m", Rgb(0.5), Rgb(1.0));
  r.addRoom({0, 0, 0}, {3, 2, 2}, {m, m, m},
            {{kYMin, {1, 0, 0.5}, {2, 0, 1.5}, 0.25, -1, m, "window"},
             {kZMax, {0.5, 0.5, 2}, {1, 1, 2}, 0, -1, m, "light"}},
            "room");
  const Scene room = r.take();
  EXPECT_NEAR(signedVolume(room.polygons), -(12.0 + 0.25), 1e-12);
  // The wall with the window is four rectangles (below, left, right, above), not one with a hole.
  EXPECT_EQ(std::count_if(room.polygons.begin(), room.polygons.end(),
                          [](const Polygon& p) { return p.origin == "room 'room' wall -y"; }),
            4);
  EXPECT_NO_THROW(validateScene(room));
}

TEST(SceneLoader, LoadsBuiltinsByNameAndFilesByExtension) {
  const Scene s = loadScene("furnace");
  EXPECT_EQ(s.source, "furnace");
  EXPECT_EQ(std::string(kDefaultScene), "office");
  const Scene gltf = loadScene((test::sourceDir() / "assets" / "cornell.gltf").string());
  EXPECT_EQ(gltf.polygons.size(), builtinScene("cornell").polygons.size());
}

// `load` (a loadScene of `path`) refused the path with a message naming it, `needle` and the
// accepted forms.
void expectRefused(const std::function<void()>& load, const std::string& path, const std::string& needle) {
  try {
    load();
    ADD_FAILURE() << "accepted " << path;
  } catch (const SceneError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find(needle), std::string::npos) << message;
    EXPECT_NE(message.find(".mgf"), std::string::npos) << message;  // lists the accepted forms
    EXPECT_NE(message.find("office"), std::string::npos) << message;
  }
}

void expectRefused(const std::string& path, const std::string& needle) {
  expectRefused([&] { loadScene(path); }, path, needle);
}

TEST(SceneLoader, RefusesMissingFilesAndUnknownExtensionsNamingThePath) {
  expectRefused("no/such/scene.gltf", "no such file");
  expectRefused((test::sourceDir() / "CMakeLists.txt").string(), "unknown extension '.txt'");
  expectRefused(test::sourceDir().string(), "directory");
}

// A FIFO named .mgf used to block the reader forever: it is refused without being opened.
TEST(SceneLoader, RefusesAFifoWithoutBlocking) {
  const test::TempDir dir;
  const std::string path = (dir / "scene.mgf").string();
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  std::future<void> load = std::async(std::launch::async, [&] { loadScene(path); });
  if (load.wait_for(std::chrono::seconds(10)) == std::future_status::timeout) {
    ADD_FAILURE() << "blocked on the FIFO";
    ::close(::open(path.c_str(), O_WRONLY));  // a writer that ends at once: the reader sees the end
  }
  expectRefused([&] { load.get(); }, path, "is not a regular file");
}

// A checkpoint renamed .glb used to be read as glTF, and refused as JSON to repair.
TEST(SceneLoader, NamesACheckpointGivenAsAScene) {
  const test::TempDir dir;
  for (const char* name : {"solve.glb", "solve.gltf", "solve.mgf"}) {
    const std::string path = (dir / name).string();
    std::ofstream(path, std::ios::binary) << "RADMESHC\x03\0\0\0 and the rest of a checkpoint";
    std::vector<std::function<void()>> reads = {[&] { loadScene(path); }};
    if (std::string(name) != "solve.mgf") reads.push_back([&] { readBake(path); });  // a bake is glTF only
    for (const auto& read : reads) {
      try {
        read();
        ADD_FAILURE() << "accepted " << path;
      } catch (const SceneError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(path + ": is a radmesh checkpoint, not a scene"), std::string::npos) << message;
        EXPECT_NE(message.find("--resume"), std::string::npos) << message;
      }
    }
  }
}

// A glTF binary named .mgf was read as MGF text: ninety warnings of unknown entities in raw bytes,
// then "contains no polygons".
TEST(SceneLoader, NamesABinaryFileGivenAsText) {
  const test::TempDir dir;
  const std::string glb = (dir / "bake.mgf").string(), noise = (dir / "noise.gltf").string();
  std::ofstream(glb, std::ios::binary) << std::string("glTF\x02\0\0\0", 8) << "the rest of a binary glTF";
  std::ofstream(noise, std::ios::binary) << std::string("\x01\0\x02\x03", 4);
  for (const auto& [path, says] : {std::pair{glb, "is glTF binary (.glb), not mgf text (fix: name it .glb)"},
                                   std::pair{noise, "is a binary file, not gltf text"}})
    try {
      loadScene(path);
      ADD_FAILURE() << "accepted " << path;
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(path + ": " + says), std::string::npos) << e.what();
    }
}

TEST(SceneLoader, LoadsSharedMgfByExtension) {
  RADMESH_REQUIRE_SHARED(path, "scenes/mgf/cube.mgf");
  const Scene s = loadScene(path.string());
  EXPECT_FALSE(s.polygons.empty());
  test::expectAreaKept(s, meshScene(s), 1e-9, path.string());
}

}  // namespace
}  // namespace radmesh
