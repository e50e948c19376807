#include "solver/meshing/grid_turn.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "solver/io/builtin_scenes.h"
#include "solver/meshing/meshing.h"
#include "tests/solver/meshing/mesh_checks.h"
#include "tests/solver/turned_scene.h"

namespace radmesh {
namespace {

using test::turnAboutVertical;
using test::turnedAboutVertical;

constexpr double kTurnCellM = 0.381;

Scene moved(Scene scene, const Vec3& by) {
  for (Polygon& p : scene.polygons)
    for (Vec3& v : p.vertices) v += by;
  return scene;
}

Scene turned(Scene scene, double degrees) {
  turnAboutVertical(scene, degrees);
  return scene;
}

// The corner of a scene's plan, low in x and y.
Vec3 planCorner(const Scene& scene) {
  Vec3 low(INFINITY);
  for (const Polygon& p : scene.polygons)
    for (const Vec3& v : p.vertices) low = glm::min(low, v);
  return {low.x, low.y, 0.0};
}

// The turned model's patches are the axis-aligned model's, turned and moved by shift: each matched by
// its polygon and centroid, its corners the same up to where the fan starts (the grid's axes may
// be a quarter turn apart).
void expectSameMeshTurned(const std::vector<Patch>& axisAligned, const std::vector<Patch>& turned, double degrees,
                          const Vec3& shift, double tolerance) {
  ASSERT_EQ(axisAligned.size(), turned.size());
  const auto moved = [&](const Vec3& p) { return turnedAboutVertical(p, degrees) + shift; };
  std::vector<bool> matched(axisAligned.size(), false);
  for (size_t i = 0; i < turned.size(); ++i) {
    const Patch& b = turned[i];
    size_t j = 0;
    while (j < axisAligned.size() && (matched[j] || axisAligned[j].polygon != b.polygon ||
                                      glm::length(moved(axisAligned[j].centroid) - b.centroid) > tolerance))
      ++j;
    ASSERT_LT(j, axisAligned.size()) << "patch " << i << " of polygon " << b.polygon << " has no match";
    matched[j] = true;
    const Patch& a = axisAligned[j];
    ASSERT_EQ(a.vertexCount, b.vertexCount) << i;
    EXPECT_NEAR(a.areaM2, b.areaM2, 1e-12 + tolerance * std::sqrt(a.areaM2)) << i;
    for (int k = 0; k < a.vertexCount; ++k) {
      double nearest = INFINITY;
      for (int m = 0; m < b.vertexCount; ++m) nearest = std::min(nearest, glm::length(moved(a.vertices[k]) - b.vertices[m]));
      ASSERT_LT(nearest, tolerance) << "patch " << i << " corner " << k;
    }
    EXPECT_LT(glm::length(turnedAboutVertical(a.normal, degrees) - b.normal), 10.0 * tolerance) << i;
    // The projection frame turns too, so the shots are the same: up to a quarter turn about the
    // normal, which maps a hemicube or a square plane onto itself (an axis of the grid's frame
    // that a normal misses by a rounding may be taken for the other).
    const Vec3 u = turnedAboutVertical(a.frame.u, degrees), v = turnedAboutVertical(a.frame.v, degrees);
    double nearest = INFINITY;
    for (const Vec3& w : {u, v, -u, -v}) nearest = std::min(nearest, glm::length(w - b.frame.u));
    EXPECT_LT(nearest, 10.0 * tolerance) << i;
  }
}

TEST(GridTurn, AModelAlongTheAxesKeepsTheWorldGrid) {
  for (const char* name : {"office", "two-rooms", "cornell", "building:3x3"}) {
    const GridTurn turn = gridTurnOf(builtinScene(name));
    EXPECT_FALSE(turn.turned()) << name << " turned by " << turn.degrees();
  }
}

TEST(GridTurn, AModelTurnedAboutAnyPointMeshesAsItselfUnturnedAtTheOrigin) {
  // two-rooms has the corner of its plan at the origin, where the world grid lines cross.
  const Scene rooms = builtinScene("two-rooms");
  ASSERT_EQ(planCorner(rooms), Vec3(0.0));
  for (const double degrees : {10.0, 30.0, 45.0, 75.0, 135.0, -20.0}) {
    SCOPED_TRACE(degrees);
    const Vec3 offset(1.234, -5.678, 0.0);
    const Scene scene = turned(moved(rooms, offset), degrees);
    const GridTurn turn = gridTurnOf(scene);
    ASSERT_TRUE(turn.turned());
    EXPECT_EQ(turn.axis, 2);
    // Modulo a quarter turn (45 degrees may go either way): the grid's own axes are the model's
    // turned by what is left.
    const double left = turn.degrees();
    EXPECT_NEAR(std::remainder(degrees - left, 90.0), 0.0, 1e-9);
    EXPECT_LE(std::abs(left), 45.0);
    // So the model lies in the grid as itself turned by the quarter turns, its corner at the origin.
    const Scene quarterTurned = turned(rooms, degrees - left);
    const Vec3 corner = planCorner(quarterTurned);
    const std::vector<Patch> reference = meshScene(moved(quarterTurned, -corner), kTurnCellM);
    test::expectValidPatches(reference, kTurnCellM, "two-rooms, quarter turns");
    const std::vector<Patch> patches = meshScene(scene, kTurnCellM);
    test::expectValidPatches(patches, kTurnCellM, "two-rooms turned", scene);
    test::expectAreaKept(scene, patches, 1e-9, "two-rooms turned");
    const Vec3 shift = turnedAboutVertical(corner, left) + turnedAboutVertical(offset, degrees);
    expectSameMeshTurned(reference, patches, left, shift, 1e-11);
  }
}

// A 1.2 x 0.6 m rectangle at `degrees` about the vertical, its corner at `corner`.
std::vector<Vec3> tableTop(const Vec3& corner, double degrees) {
  std::vector<Vec3> top;
  for (const Vec3& v : {Vec3(0, 0, 0), Vec3(1.2, 0, 0), Vec3(1.2, 0.6, 0), Vec3(0, 0.6, 0)})
    top.push_back(corner + turnedAboutVertical(v, degrees));
  return top;
}

TEST(GridTurn, ATableAtAnAngleGetsAGridOfItsOwnAndTheRoomsKeepTheWorlds) {
  // A table top at 20 degrees in the axis-aligned rooms: the model's grid stays the world's, and the
  // table is meshed as if along the axes, its corner at the origin: 4 x 2 cells, no slivers. On
  // the world grid it made 15 patches, 2 of them under a tenth of a cell wide.
  Scene rooms = builtinScene("two-rooms");
  const size_t roomPolygons = rooms.polygons.size();
  rooms.polygons.push_back({tableTop({0.5, 0.5, 0.75}, 20.0), 0, "table"});
  EXPECT_FALSE(gridTurnOf(rooms).turned());
  const Grids grids = gridsOf(rooms);
  ASSERT_EQ(grids.turns.size(), 1u);
  EXPECT_TRUE(grids.turns[0].own);
  EXPECT_EQ(grids.outlinesOnOwnGrids(), 1u);
  EXPECT_NEAR(grids.turns[0].degrees(), 20.0, 1e-9);
  EXPECT_EQ(grids.turnOf[roomPolygons], 0);
  for (size_t i = 0; i < roomPolygons; ++i) EXPECT_EQ(grids.turnOf[i], -1) << "polygon " << i;
  const std::vector<Patch> patches = meshScene(rooms, kTurnCellM);
  test::expectValidPatches(patches, kTurnCellM, "rooms and table", rooms);
  test::expectAreaKept(rooms, patches, 1e-9, "rooms and table");
  EXPECT_EQ(patches.size(), meshScene(builtinScene("two-rooms"), kTurnCellM).size() + 8);
  // The rooms turned by 30 degrees, the table with them: the model's grid turns by the rooms' 30.
  turnAboutVertical(rooms, 30.0);
  EXPECT_NEAR(gridTurnOf(rooms).degrees(), 30.0, 1e-9);
}

// A round column of 16 facets 0.2 m wide: each facet on a grid of its own is cut only at the
// world's heights, into 7 strips from floor to 2.5 m. On the world grid the lines crossing the
// facets cut them into 161 patches, not 112.
TEST(GridTurn, EachFacetOfARoundColumnIsCutOnlyAcrossItsHeight) {
  constexpr int kFacets = 16;
  constexpr double kRadiusM = 0.5, kHeightM = 2.5;
  Scene column = builtinScene("two-rooms");
  const size_t roomPolygons = column.polygons.size();
  const Vec3 centre(2.0, 1.5, 0.0);
  for (int k = 0; k < kFacets; ++k) {
    const auto at = [&](int i, double z) {
      const double a = 2.0 * std::numbers::pi * (i + 0.1) / kFacets;
      return centre + Vec3(kRadiusM * std::cos(a), kRadiusM * std::sin(a), z);
    };
    column.polygons.push_back({{at(k, 0.0), at(k + 1, 0.0), at(k + 1, kHeightM), at(k, kHeightM)}, 0, "column"});
  }
  const Grids grids = gridsOf(column);
  EXPECT_EQ(grids.outlinesOnOwnGrids(), static_cast<size_t>(kFacets));
  const std::vector<Patch> patches = meshScene(column, kTurnCellM);
  test::expectValidPatches(patches, kTurnCellM, "column", column);
  test::expectAreaKept(column, patches, 1e-9, "column");
  std::vector<int> strips(kFacets, 0);
  for (const Patch& p : patches)
    if (p.polygon >= static_cast<int>(roomPolygons)) {
      ++strips[p.polygon - roomPolygons];
      EXPECT_NEAR(p.areaM2 / (2.0 * kRadiusM * std::sin(std::numbers::pi / kFacets)),
                  p.centroid.z < 6 * kTurnCellM ? kTurnCellM : kHeightM - 6 * kTurnCellM, 1e-9);
    }
  for (int k = 0; k < kFacets; ++k) EXPECT_EQ(strips[k], 7) << "facet " << k;
}

// A building of two wings, one along the axes and one at 30 degrees to them: each is meshed on its
// own grid, as it would be alone.
TEST(GridTurn, EachWingOfABuildingIsMeshedOnItsOwnGrid) {
  const Scene along = builtinScene("two-rooms");
  const Scene wing = moved(turned(along, 30.0), Vec3(14.0, 3.0, 0.0));
  Scene building = along;
  building.polygons.insert(building.polygons.end(), wing.polygons.begin(), wing.polygons.end());
  const Grids grids = gridsOf(building);
  ASSERT_EQ(grids.turns.size(), 1u);
  EXPECT_NEAR(grids.turns[0].degrees(), 30.0, 1e-9);
  for (size_t i = 0; i < building.polygons.size(); ++i)
    EXPECT_EQ(grids.turnOf[i], i < along.polygons.size() ? -1 : 0) << "polygon " << i;
  const std::vector<Patch> patches = meshScene(building, kTurnCellM);
  const std::vector<Patch> first = meshScene(along, kTurnCellM), second = meshScene(wing, kTurnCellM);
  ASSERT_EQ(patches.size(), first.size() + second.size());
  for (size_t k = 0; k < patches.size(); ++k) {
    const bool inFirst = k < first.size();
    const Patch& alone = inFirst ? first[k] : second[k - first.size()];
    ASSERT_EQ(patches[k].vertexCount, alone.vertexCount) << k;
    for (int v = 0; v < alone.vertexCount; ++v) ASSERT_EQ(patches[k].vertices[v], alone.vertices[v]) << k;
    EXPECT_EQ(patches[k].frame.u, alone.frame.u) << k;
  }
}

// Patches under a tenth of a cell wide.
long slivers(const std::vector<Patch>& patches, int fromPolygon) {
  return std::count_if(patches.begin(), patches.end(), [&](const Patch& p) {
    double longest = 0.0;
    for (int k = 0; k < p.vertexCount; ++k)
      longest = std::max(longest, glm::length(p.vertices[(k + 1) % p.vertexCount] - p.vertices[k]));
    return p.polygon >= fromPolygon && p.areaM2 / longest < 0.1 * kTurnCellM;
  });
}

// A wing too small for a turn of the model's (a fifth of its edge length): its polygons on grids of
// their own make no more patches and slivers than the wing alone on its turned grid (1229 and 112
// against 1262 and 131), where the world grid cut it into 1382, 167 of them slivers.
TEST(GridTurn, AWingTooSmallForATurnOfTheModelsIsMeshedAsWellAsAlone) {
  const Scene rooms = builtinScene("two-rooms");
  Scene building;
  for (int k = 0; k < 4; ++k) {
    const Scene copy = moved(rooms, Vec3(0.0, 4.0 * k, 0.0));
    building.polygons.insert(building.polygons.end(), copy.polygons.begin(), copy.polygons.end());
  }
  building.materials = rooms.materials;
  const int along = static_cast<int>(building.polygons.size());
  const Scene wing = moved(turned(rooms, 30.0), Vec3(12.0, 0.0, 0.0));
  building.polygons.insert(building.polygons.end(), wing.polygons.begin(), wing.polygons.end());
  const Grids grids = gridsOf(building);
  EXPECT_FALSE(grids.principal().turned());
  EXPECT_EQ(grids.outlinesOnOwnGrids(), wing.polygons.size());
  const std::vector<Patch> patches = meshScene(building, kTurnCellM);
  test::expectValidPatches(patches, kTurnCellM, "four blocks and a wing", building);
  test::expectAreaKept(building, patches, 1e-9, "four blocks and a wing");
  const long onWing =
      std::count_if(patches.begin(), patches.end(), [&](const Patch& p) { return p.polygon >= along; });
  const std::vector<Patch> alone = meshScene(wing, kTurnCellM);
  EXPECT_LE(onWing, static_cast<long>(alone.size()));
  EXPECT_LE(slivers(patches, along), slivers(alone, 0));
}

// A house 3.75 x 3 m with walls 2.5 m high under a gable roof pitched 36.87 degrees (rise 1.125 m
// over 1.5 m): each slope is 3.75 x 1.875 m, 10 x 5 cells of 0.375 m. Its corner at the origin.
constexpr double kRoofCellM = 0.375;
Scene gableHouse() {
  const double w = 3.75, d = 3.0, h = 2.5, top = h + 1.125;
  Scene house;
  house.materials.push_back({});
  const auto add = [&](std::vector<Vec3> outline, const char* name) { house.polygons.push_back({outline, 0, name}); };
  add({{0, 0, 0}, {0, d, 0}, {w, d, 0}, {w, 0, 0}}, "floor");
  add({{0, 0, 0}, {w, 0, 0}, {w, 0, h}, {0, 0, h}}, "front");
  add({{w, d, 0}, {0, d, 0}, {0, d, h}, {w, d, h}}, "back");
  add({{0, d, 0}, {0, 0, 0}, {0, 0, h}, {0, d / 2, top}, {0, d, h}}, "west gable");
  add({{w, 0, 0}, {w, d, 0}, {w, d, h}, {w, d / 2, top}, {w, 0, h}}, "east gable");
  add({{0, 0, h}, {w, 0, h}, {w, d / 2, top}, {0, d / 2, top}}, "south slope");
  add({{w, d, h}, {0, d, h}, {0, d / 2, top}, {w, d / 2, top}}, "north slope");
  return house;
}

// A roof slope lies flat on a grid of its own, tilted with it, so it is cut into 0.375 m squares;
// on the grid below it, its patches were 1 / cos(36.87 degrees) = 1.25 times as long up the slope
// (40 of them a slope, not 50). The house turned 17 degrees in plan, where its walls' grid is
// turned and the slopes' grids are tilted from that one, meshes as along the axes.
TEST(GridTurn, ARoofSlopeIsCutIntoSquaresOnAHouseTurnedInPlan) {
  const Scene along = gableHouse();
  const std::vector<Patch> reference = meshScene(along, kRoofCellM);
  test::expectValidPatches(reference, kRoofCellM, "house", along);
  for (const int slope : {5, 6}) {
    EXPECT_EQ(std::count_if(reference.begin(), reference.end(), [&](const Patch& p) { return p.polygon == slope; }), 50);
    for (const Patch& p : reference)
      if (p.polygon == slope) {
        ASSERT_NEAR(p.areaM2, kRoofCellM * kRoofCellM, 1e-12);
      }
  }
  const Vec3 site(20.0, -7.0, 0.0);
  const Scene scene = moved(turned(along, 17.0), site);
  const Grids grids = gridsOf(scene);
  ASSERT_NEAR(grids.principal().degrees(), 17.0, 1e-9);
  EXPECT_EQ(grids.outlinesOnOwnGrids(), 2u);
  const std::vector<Patch> patches = meshScene(scene, kRoofCellM);
  test::expectValidPatches(patches, kRoofCellM, "house turned", scene);
  test::expectAreaKept(scene, patches, 1e-9, "house turned");
  expectSameMeshTurned(reference, patches, 17.0, site, 1e-10);
}

// A hip roof's end: a trapezoid whose sloping sides follow no grid, along the axes. Its plane
// is tilted about x, so it is cut on a grid tilted with it: no patch longer than a cell up the
// slope (0.469 m on the world grid).
TEST(GridTurn, AHipRoofsEndIsCutOnAGridTiltedWithIt) {
  Scene house = gableHouse();
  const double h = 2.5, top = h + 1.125;
  house.polygons.push_back({{{0, 0, h}, {3.75, 0, h}, {2.25, 1.5, top}, {1.5, 1.5, top}}, 0, "hip end"});
  const int hip = static_cast<int>(house.polygons.size()) - 1;
  const Grids grids = gridsOf(house);
  EXPECT_TRUE(grids.of(hip).own);
  const std::vector<Patch> patches = meshScene(house, kRoofCellM);
  test::expectValidPatches(patches, kRoofCellM, "hip end", house);
  test::expectAreaKept(house, patches, 1e-9, "hip end");
  const Vec3 upSlope(0.0, 0.8, 0.6);
  for (const Patch& p : patches) {
    if (p.polygon != hip) continue;
    double low = INFINITY, high = -INFINITY;
    for (int k = 0; k < p.vertexCount; ++k)
      low = std::min(low, glm::dot(p.vertices[k], upSlope)), high = std::max(high, glm::dot(p.vertices[k], upSlope));
    EXPECT_LE(high - low, kRoofCellM + 1e-9);
  }
}

TEST(GridTurn, AModelWithYUpTurnsAboutY) {
  Scene scene = turned(builtinScene("two-rooms"), 25.0);
  for (Polygon& p : scene.polygons)
    for (Vec3& v : p.vertices) v = {v.x, v.z, -v.y};
  const GridTurn turn = gridTurnOf(scene);
  EXPECT_EQ(turn.axis, 1);
  EXPECT_NEAR(std::abs(turn.degrees()), 25.0, 1e-9);
  const std::vector<Patch> patches = meshScene(scene, kTurnCellM);
  EXPECT_EQ(patches.size(), meshScene(builtinScene("two-rooms"), kTurnCellM).size());
  test::expectAreaKept(scene, patches, 1e-9, "two-rooms, y up, turned");
}

TEST(GridTurn, ATurnedModelFarFromTheOriginMeshesAsAtTheOrigin) {
  // Site coordinates, UTM-sized: a vertex there is only known to about 1e-9 m.
  const Scene rooms = builtinScene("two-rooms");
  const Vec3 site(512345.678, 5012345.678, 0.0);
  const Scene far = moved(turned(rooms, 30.0), site);
  const std::vector<Patch> patches = meshScene(far, kTurnCellM);
  test::expectValidPatches(patches, kTurnCellM, "two-rooms turned, far out", far);
  test::expectAreaKept(far, patches, 1e-9, "two-rooms turned, far out");
  expectSameMeshTurned(meshScene(rooms, kTurnCellM), patches, 30.0, site, 1e-8);
}

}  // namespace
}  // namespace radmesh
