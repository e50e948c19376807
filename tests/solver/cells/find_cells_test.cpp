#include "solver/cells/find_cells.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "solver/io/builtin_building.h"
#include "solver/io/builtin_scenes.h"
#include "solver/io/scene_builder.h"
#include "solver/meshing/meshing.h"
#include "tests/solver/turned_scene.h"

namespace radmesh {
namespace {

struct Found {
  Scene scene;
  std::vector<Patch> patches;
  CellPartition cells;
};

// A built-in scene, turned about the vertical by `degrees`, meshed and its cells found.
Found find(const std::string& name, double degrees = 0.0) {
  Found f{builtinScene(name), {}, {}};
  test::turnAboutVertical(f.scene, degrees);
  f.patches = meshScene(f.scene);
  f.cells = findCells(f.scene, f.patches);
  return f;
}

std::map<std::string, int> cellIndexByName(const CellPartition& p) {
  std::map<std::string, int> out;
  for (size_t c = 0; c < p.cells.size(); ++c) out[p.cells[c].name] = int(c);
  return out;
}

Vec3 portalNormal(const Portal& p) { return glm::normalize(newellNormal(p.vertices)); }

// Does segment [a, b] lie on segment [c, d] (collinear, inside it)?
bool segmentOn(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 u = d - c;
  const double length = glm::length(u);
  if (length < 1e-12) return false;
  for (const Vec3& p : {a, b}) {
    const double along = glm::dot(p - c, u) / length;
    if (glm::length(p - c - u * (along / length)) > 1e-6 || along < -1e-6 || along > length + 1e-6) return false;
  }
  return true;
}

// Whether every edge of the portal runs along an edge of some polygon of the scene: the portal is
// framed by the wall, the floor and the reveals of its opening, not placed beside it.
bool framedByGeometry(const Scene& scene, const Portal& portal) {
  const size_t n = portal.vertices.size();
  for (size_t k = 0; k < n; ++k) {
    const Vec3 a = portal.vertices[k], b = portal.vertices[(k + 1) % n];
    bool framed = false;
    for (const Polygon& poly : scene.polygons) {
      const size_t m = poly.vertices.size();
      for (size_t j = 0; j < m && !framed; ++j) framed = segmentOn(a, b, poly.vertices[j], poly.vertices[(j + 1) % m]);
      if (framed) break;
    }
    if (!framed) return false;
  }
  return true;
}

TEST(FindCells, OneRoomIsOneCellWithoutPortals) {
  for (const std::string name : {"office", "cornell", "furnace"}) {
    SCOPED_TRACE(name);
    const Found f = find(name);
    ASSERT_EQ(f.cells.cells.size(), 1u);
    EXPECT_TRUE(f.cells.portals.empty());
    ASSERT_EQ(f.cells.cellOfPatch.size(), f.patches.size());
    EXPECT_EQ(std::count(f.cells.cellOfPatch.begin(), f.cells.cellOfPatch.end(), 0), long(f.patches.size()))
        << "every patch of a closed room faces into it";
  }
  EXPECT_EQ(find("office").cells.cells[0].name, "office");
}

TEST(FindCells, TwoRoomsAreTwoCellsJoinedByTheDoorway) {
  const Found f = find("two-rooms");
  ASSERT_EQ(f.cells.cells.size(), 2u);
  ASSERT_EQ(f.cells.portals.size(), 1u);
  const auto index = cellIndexByName(f.cells);
  ASSERT_TRUE(index.count("first") && index.count("second"));
  const Portal& p = f.cells.portals[0];
  EXPECT_EQ(std::set<int>({p.cellA, p.cellB}), std::set<int>({0, 1}));
  EXPECT_LT(p.cellA, p.cellB);
  // The doorway, 0.9 m x 2.1 m, in one of the wall's two faces (x = 4 or x = 4.2).
  EXPECT_NEAR(p.areaM2, 0.9 * 2.1, 1e-6);
  EXPECT_NEAR(polygonArea(p.vertices), 0.9 * 2.1, 1e-6);
  const double x = p.vertices[0].x;
  EXPECT_TRUE(std::abs(x - 4.0) < 1e-9 || std::abs(x - 4.2) < 1e-9) << x;
  for (const Vec3& v : p.vertices) {
    EXPECT_NEAR(v.x, x, 1e-12);
    EXPECT_TRUE(std::abs(v.y - 1.55) < 1e-9 || std::abs(v.y - 2.45) < 1e-9) << v.y;
    EXPECT_TRUE(std::abs(v.z) < 1e-9 || std::abs(v.z - 2.1) < 1e-9) << v.z;
  }
  // Oriented from cellA into cellB: "first" lies at x < 4.
  const double towardsSecond = p.cellB == index.at("second") ? 1.0 : -1.0;
  EXPECT_NEAR(portalNormal(p).x, towardsSecond, 1e-12);
  EXPECT_TRUE(framedByGeometry(f.scene, p));
  Portal beside = p;  // the same rectangle 10 cm along the wall is not framed
  for (Vec3& v : beside.vertices) v.y += 0.1;
  EXPECT_FALSE(framedByGeometry(f.scene, beside));
  // Each room's floor, walls and ceiling in its own cell.
  for (size_t i = 0; i < f.patches.size(); ++i) {
    const std::string group = groupOfOrigin(f.scene.polygons[f.patches[i].polygon].origin);
    const std::string& origin = f.scene.polygons[f.patches[i].polygon].origin;
    if (origin.find("opening") != std::string::npos) continue;  // the doorway's reveals lie between the two
    EXPECT_EQ(f.cells.cellOfPatch[i], index.at(group)) << origin;
  }
}

// Buildings are rarely drawn along the axes. two-rooms turned about its vertical: the portal is
// still the whole doorway, in the wall's plane (before 2026-12-04, the voxels' rectangle across one
// axis: 1.08 m² at 30°, 0.81 m² at 45°, so that light went past it), and every patch of a room's
// floor, walls and ceiling is in its room (the floor just past the door was the other room's,
// whose voxels reach a little past the door's plane; a wall's end in a corner took the voxel past
// the wall it runs into).
TEST(FindCells, TwoRoomsAtAnAngleToTheAxesAreJoinedByTheWholeDoorway) {
  for (const double degrees : {10.0, 30.0, 45.0, 75.0, 135.0}) {
    SCOPED_TRACE(degrees);
    const Found f = find("two-rooms", degrees);
    ASSERT_EQ(f.cells.cells.size(), 2u);
    ASSERT_EQ(f.cells.portals.size(), 1u);
    const Portal& p = f.cells.portals[0];
    EXPECT_NEAR(p.areaM2, 0.9 * 2.1, 1e-6);
    EXPECT_NEAR(polygonArea(p.vertices), 0.9 * 2.1, 1e-6);
    EXPECT_TRUE(framedByGeometry(f.scene, p));
    const auto index = cellIndexByName(f.cells);
    ASSERT_TRUE(index.count("first") && index.count("second"));
    // Across the dividing wall, from the first room into the second.
    const Vec3 across = test::turnedAboutVertical(Vec3(1, 0, 0), degrees);
    const Vec3 towardsSecond = p.cellB == index.at("second") ? across : -across;
    EXPECT_NEAR(glm::dot(portalNormal(p), towardsSecond), 1.0, 1e-12);
    for (size_t i = 0; i < f.patches.size(); ++i) {
      const std::string& origin = f.scene.polygons[f.patches[i].polygon].origin;
      if (origin.find("opening") != std::string::npos) continue;  // the doorway's reveals lie between the two
      EXPECT_EQ(f.cells.cellOfPatch[i], index.at(groupOfOrigin(origin))) << origin;
    }
  }
}

// The generator's rooms and corridors, each its own cell named for it, and each door one portal
// between the room and its corridor (or a wing's corridor and the spine).
void expectBuildingCells(const std::string& name, double degrees = 0.0) {
  SCOPED_TRACE(name + " turned by " + std::to_string(degrees));
  const BuildingLayout layout = parseBuildingName(name);
  const Found f = find(name, degrees);
  EXPECT_EQ(int(f.cells.cells.size()), layout.rooms() + layout.corridors());
  ASSERT_EQ(int(f.cells.portals.size()), layout.doors());
  const auto index = cellIndexByName(f.cells);
  std::set<std::pair<int, int>> expected;
  auto join = [&](const std::string& a, const std::string& b) {
    ASSERT_TRUE(index.count(a)) << a;
    ASSERT_TRUE(index.count(b)) << b;
    expected.insert({std::min(index.at(a), index.at(b)), std::max(index.at(a), index.at(b))});
  };
  for (int w = 0; w < layout.wings(); ++w) {
    join(buildingCorridorName(w), kBuildingSpineName);
    for (int row = 2 * w; row < std::min(2 * w + 2, layout.rows); ++row)
      for (int col = 0; col < layout.cols; ++col) join(buildingRoomName(col, row), buildingCorridorName(w));
  }
  std::set<std::pair<int, int>> found;
  for (const Portal& p : f.cells.portals) {
    EXPECT_LT(p.cellA, p.cellB);
    found.insert({p.cellA, p.cellB});
    EXPECT_NEAR(p.areaM2, 0.9 * 2.1, 1e-6);
    EXPECT_NEAR(polygonArea(p.vertices), 0.9 * 2.1, 1e-6);
    EXPECT_TRUE(framedByGeometry(f.scene, p)) << "portal " << p.cellA << "-" << p.cellB;
    // Its normal points from cellA's side into cellB's: cellB's bounds lie ahead of the portal.
    const Vec3 n = portalNormal(p), mid = 0.5 * (f.cells.cells[p.cellB].boundsMin + f.cells.cells[p.cellB].boundsMax);
    EXPECT_GT(glm::dot(mid - p.vertices[0], n), 0.0);
  }
  EXPECT_EQ(found, expected);
  // Every floor patch in the cell of its room or corridor; the counts add up.
  long inCells = 0;
  for (size_t i = 0; i < f.patches.size(); ++i) {
    const std::string& origin = f.scene.polygons[f.patches[i].polygon].origin;
    if (origin.find(" floor") != std::string::npos) {
      EXPECT_EQ(f.cells.cellOfPatch[i], index.at(groupOfOrigin(origin))) << origin;
    }
    inCells += f.cells.cellOfPatch[i] >= 0 ? 1 : 0;
  }
  const long outside = std::count(f.cells.cellOfPatch.begin(), f.cells.cellOfPatch.end(), kOutsideCell);
  EXPECT_EQ(inCells + outside, long(f.patches.size()));
}

TEST(FindCells, BuildingGivesTheGeneratorsRoomsAndDoors) {
  expectBuildingCells("building:1x1");
  expectBuildingCells("building:2x2");
  expectBuildingCells("building:3x1");
  expectBuildingCells("building:2x2", 30.0);  // each door's portal exact in its turned wall
  expectBuildingCells("building:3x1", 60.0);
}

// A box standing outside a closed room faces no cell; the room's own faces, and a cabinet 2 cm
// from its wall with nothing but the outside behind that wall, face the room.
TEST(FindCells, AFaceTowardsTheOutsideHasNoCell) {
  SceneBuilder b("test");
  const int grey = b.addMaterial("grey", Rgb(0.5)), light = b.addMaterial("light", Rgb(0.5), Rgb(1.0));
  b.addRoom({0, 0, 0}, {4, 4, 2.7}, {grey, grey, grey}, {{kZMax, {1, 1, 0}, {2, 2, 0}, 0.0, -1, light, "light"}},
            "room");
  b.addBox({3.38, 1, 0}, {3.98, 1.5, 1.3}, grey, "cabinet", kZMin);
  b.addBox({6, 1, 0}, {7, 2, 1}, grey, "shed", kZMin);
  const Scene scene = b.take();
  const std::vector<Patch> patches = meshScene(scene);
  const CellPartition cells = findCells(scene, patches);
  ASSERT_EQ(cells.cells.size(), 1u);
  EXPECT_EQ(cells.cells[0].name, "room");
  for (size_t i = 0; i < patches.size(); ++i) {
    const std::string& origin = scene.polygons[patches[i].polygon].origin;
    EXPECT_EQ(cells.cellOfPatch[i], origin.find("shed") != std::string::npos ? kOutsideCell : 0) << origin;
  }
}

// A closed crate in a room encloses space no patch faces: it used to be a cell of no patches, which
// refused the whole solve ("meshed into no patches"); the shared scenes' cube.mgf has two.
TEST(FindCells, TheInsideOfASolidObjectIsNoCell) {
  SceneBuilder b("test");
  const int grey = b.addMaterial("grey", Rgb(0.5)), light = b.addMaterial("light", Rgb(0.5), Rgb(1.0));
  b.addRoom({0, 0, 0}, {6, 6, 3}, {grey, grey, grey}, {{kZMax, {1, 1, 0}, {2, 2, 0}, 0.0, -1, light, "light"}},
            "room");
  b.addBox({2, 2, 0.5}, {4, 4, 2}, grey, "crate");  // all six faces, looking out
  const Scene scene = b.take();
  const std::vector<Patch> patches = meshScene(scene);
  const CellPartition cells = findCells(scene, patches);
  ASSERT_EQ(cells.cells.size(), 1u);
  EXPECT_EQ(cells.cells[0].name, "room");
  EXPECT_TRUE(cells.portals.empty());
  EXPECT_EQ(std::count(cells.cellOfPatch.begin(), cells.cellOfPatch.end(), 0), long(patches.size()));
}

// Two rooms sharing a wall of no thickness (each room's own face, back to back, as files often
// have them), joined by an opening `width` m wide and 2.1 m high.
Scene abuttingRooms(double width, const std::string& west = "west", const std::string& east = "east") {
  SceneBuilder b("test");
  const int grey = b.addMaterial("grey", Rgb(0.5)), light = b.addMaterial("light", Rgb(0.5), Rgb(1.0));
  const double y0 = 2.0 - width / 2, y1 = 2.0 + width / 2;
  b.addRoom({0, 0, 0}, {4, 4, 2.7}, {grey, grey, grey},
            {{kXMax, {4, y0, 0}, {4, y1, 2.1}, 0.0, -1, -1, "opening"},
             {kZMax, {1, 1, 0}, {2, 2, 0}, 0.0, -1, light, "light"}},
            west);
  b.addRoom({4, 0, 0}, {8, 4, 2.7}, {grey, grey, grey}, {{kXMin, {4, y0, 0}, {4, y1, 2.1}, 0.0, -1, -1, "opening"}},
            east);
  return b.take();
}

// A door in a wall of no thickness is cut and its portal lies in the wall's plane; an opening
// wider than the cut (2 m) joins the two rooms into one cell, as docs/cells.md says.
TEST(FindCells, ThinWallsAndWideOpenings) {
  const Scene door = abuttingRooms(0.9);
  const CellPartition cells = findCells(door, meshScene(door));
  ASSERT_EQ(cells.cells.size(), 2u);
  ASSERT_EQ(cells.portals.size(), 1u);
  const Portal& p = cells.portals[0];
  EXPECT_NEAR(p.areaM2, 0.9 * 2.1, 1e-9);
  for (const Vec3& v : p.vertices) EXPECT_NEAR(v.x, 4.0, 1e-12);
  EXPECT_TRUE(framedByGeometry(door, p));
  EXPECT_EQ(cells.cells[p.cellA].name, "west");
  EXPECT_NEAR(portalNormal(p).x, 1.0, 1e-12) << "from the west room into the east";

  const Scene arch = abuttingRooms(2.0);
  const CellPartition one = findCells(arch, meshScene(arch));
  EXPECT_EQ(one.cells.size(), 1u);
  EXPECT_TRUE(one.portals.empty());
}

// Two rooms the file names as one ("hall"): by default two cells (the second named "cell 1"), with
// CellGroups::Join one cell named "hall" holding every patch, and no portal.
TEST(FindCells, NamedGroupsJoinCellsWhenAsked) {
  const Scene hall = abuttingRooms(0.9, "hall", "hall");
  const std::vector<Patch> patches = meshScene(hall);
  const CellPartition two = findCells(hall, patches);
  ASSERT_EQ(two.cells.size(), 2u);
  EXPECT_EQ(two.cells[0].name, "hall");
  EXPECT_EQ(two.cells[1].name, "cell 1");
  EXPECT_EQ(two.portals.size(), 1u);
  const CellPartition one = findCells(hall, patches, CellGroups::Join);
  ASSERT_EQ(one.cells.size(), 1u);
  EXPECT_EQ(one.cells[0].name, "hall");
  EXPECT_TRUE(one.portals.empty());
  EXPECT_EQ(std::count(one.cellOfPatch.begin(), one.cellOfPatch.end(), 0), long(patches.size()));
  EXPECT_NEAR(one.cells[0].boundsMin.x, two.cells[0].boundsMin.x, 1e-12);
  EXPECT_NEAR(one.cells[0].boundsMax.x, two.cells[1].boundsMax.x, 1e-12);
  // Rooms of different names stay apart.
  const Scene apart = abuttingRooms(0.9);
  EXPECT_EQ(findCells(apart, meshScene(apart), CellGroups::Join).cells.size(), 2u);
}

TEST(FindCells, GroupOfOriginReadsRoomsAndObjects) {
  EXPECT_EQ(groupOfOrigin("room 'r1c2' wall -x"), "r1c2");
  EXPECT_EQ(groupOfOrigin("house.mgf line 7: f (object 'kitchen/table')"), "kitchen");
  EXPECT_EQ(groupOfOrigin("box 'desk' +z"), "");
}

}  // namespace
}  // namespace radmesh
