#include "solver/meshing/grid_turn.h"
#include "solver/meshing/meshing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "solver/io/builtin_scenes.h"
#include "solver/io/mgf_import.h"
#include "solver/geometry/polygon_2d.h"
#include "solver/scene/scene_error.h"
#include "tests/solver/meshing/mesh_checks.h"
#include "tests/test_paths.h"

namespace radmesh {
namespace {

using test::expectAreaKept;
using test::expectValidPatches;

Scene sceneOf(std::vector<std::vector<Vec3>> polygons) {
  Scene s;
  s.source = "test";
  s.materials.push_back({"grey", Rgb(0.5), Rgb(1.0)});
  for (auto& p : polygons) s.polygons.push_back({std::move(p), 0, "test polygon"});
  return s;
}

std::vector<Vec3> rectangleXY(double x0, double y0, double x1, double y1, double z = 0.0) {
  return {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
}

std::vector<double> sortedAreas(const std::vector<Patch>& patches) {
  std::vector<double> areas;
  for (const Patch& p : patches) areas.push_back(p.areaM2);
  std::sort(areas.begin(), areas.end());
  return areas;
}

int countWithVertices(const std::vector<Patch>& patches, int n) {
  return static_cast<int>(
      std::count_if(patches.begin(), patches.end(), [n](const Patch& p) { return p.vertexCount == n; }));
}

// Deterministic on every platform: raw mt19937 words, not std:: distributions.
struct Random {
  std::mt19937 engine;
  explicit Random(unsigned seed) : engine(seed) {}
  double uniform(double lo, double hi) { return lo + (hi - lo) * (engine() / 4294967296.0); }
};

// An orthonormal basis (e1, e2, n) for a random plane orientation.
std::array<Vec3, 3> randomBasis(Random& r) {
  Vec3 n;
  do n = {r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
  while (glm::length(n) < 0.1 || glm::length(n) > 1.0);
  n = glm::normalize(n);
  const Vec3 helper = std::abs(n.x) < 0.5 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 e1 = glm::normalize(glm::cross(helper, n));
  return {e1, glm::cross(n, e1), n};
}

std::vector<Vec3> placed(const std::vector<Vec2>& outline, const std::array<Vec3, 3>& basis, const Vec3& at) {
  std::vector<Vec3> out;
  for (const Vec2& q : outline) out.push_back(at + q.x * basis[0] + q.y * basis[1]);
  return out;
}

// Is a point of the polygon's plane inside it (even-odd rule, in the plane's dominant projection)?
bool insidePolygon(const std::vector<Vec3>& polygon, const Vec3& p) {
  const int n = test::dominantAxis(newellNormal(polygon));
  const int u = (n + 1) % 3, v = (n + 2) % 3;
  bool inside = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec3 &a = polygon[i], &b = polygon[j];
    if ((a[v] > p[v]) != (b[v] > p[v]) && p[u] < (b[u] - a[u]) * (p[v] - a[v]) / (b[v] - a[v]) + a[u])
      inside = !inside;
  }
  return inside;
}

// Without --cell: rooms keep the paper's cell, small models and campuses get one of their size.
TEST(Meshing, TheDefaultCellFollowsTheModelsSize) {
  const auto box = [](Vec3 size) {
    Scene s;
    const Vec3 o(0.0);
    s.polygons.push_back({{o, {size.x, 0, 0}, {size.x, size.y, 0}, {0, size.y, 0}}, 0, "floor"});
    s.polygons.push_back({{o, {0, 0, size.z}, {size.x, 0, size.z}, {size.x, 0, 0}}, 0, "wall"});
    return s;
  };
  const CellChoice room = chooseCell(box({5.0, 4.0, 2.7}));
  EXPECT_EQ(room.cellM, kDefaultCellM);
  EXPECT_NE(room.why.find("15 inches"), std::string::npos) << room.why;
  const CellChoice cornell = chooseCell(box({0.556, 0.559, 0.548}));
  EXPECT_DOUBLE_EQ(cornell.cellM, 0.548 / 16.0);
  EXPECT_NE(cornell.why.find("smaller than a room"), std::string::npos) << cornell.why;
  Scene wallAlone = box({1.0, 0.0, 1.2});
  wallAlone.polygons.erase(wallAlone.polygons.begin());  // the floor is flat: no area
  const CellChoice wall = chooseCell(wallAlone);  // flat: sized by its shorter side
  EXPECT_DOUBLE_EQ(wall.cellM, 1.0 / 16.0);
  // An object smaller than a room but thin (a luminaire, 1.2 x 0.26 x 0.09 m): a sixteenth of its
  // 0.09 m would make 13 000 patches; it gets about a room's.
  const Scene luminaire = box({1.2, 0.26, 0.09});
  const CellChoice object = chooseCell(luminaire);
  EXPECT_GT(object.cellM, 0.09 / 16.0) << object.why;
  const double objectPatches = static_cast<double>(meshScene(luminaire, object.cellM).size());
  EXPECT_LE(objectPatches, 1.25 * kObjectPatchBudget) << object.why;
  EXPECT_GE(objectPatches, 0.5 * kObjectPatchBudget) << object.why;
  EXPECT_NE(object.why.find("an object smaller than a room"), std::string::npos) << object.why;
  const CellChoice campus = chooseCell(box({400.0, 300.0, 20.0}));  // 400*300 + 400*20 m^2
  EXPECT_DOUBLE_EQ(campus.cellM, std::sqrt((400.0 * 300.0 + 400.0 * 20.0) / kCellPatchBudget));
  EXPECT_NEAR(static_cast<double>(meshScene(box({400.0, 300.0, 20.0}), campus.cellM).size()), kCellPatchBudget,
              0.02 * kCellPatchBudget);
  // Narrow polygons (a building's walls) make partial patches: 40 000 strips 0.2 m x 20 m would be
  // 920 000 patches at the cell of their area (0.89 m); the chosen cell keeps to about the budget.
  Scene strips;
  strips.materials.push_back(Material{});
  for (int k = 0; k < 40'000; ++k) {
    const double x = (k % 200) * 1.0, y = (k / 200) * 25.0;
    strips.polygons.push_back({{{x, y, 0.0}, {x + 0.2, y, 0.0}, {x + 0.2, y + 20.0, 0.0}, {x, y + 20.0, 0.0}}, 0, "strip"});
  }
  const CellChoice stripsCell = chooseCell(strips);
  EXPECT_GT(stripsCell.cellM, 2.0 * std::sqrt(40'000 * 4.0 / kCellPatchBudget)) << stripsCell.why;
  const double count = static_cast<double>(meshScene(strips, stripsCell.cellM).size());
  EXPECT_LE(count, 1.25 * kCellPatchBudget) << stripsCell.why;
  EXPECT_GE(count, 0.5 * kCellPatchBudget) << stripsCell.why;
  EXPECT_NE(stripsCell.why.find("at most about 200000 patches"), std::string::npos) << stripsCell.why;
  // Narrower than a room but 1000 m long: a sixteenth of its 1 m would be 1 M patches; the budget
  // holds for it too.
  const CellChoice corridor = chooseCell(box({1000.0, 1.0, 1.0}));
  EXPECT_DOUBLE_EQ(corridor.cellM, std::sqrt(2000.0 / kCellPatchBudget)) << corridor.why;
  EXPECT_LE(static_cast<double>(meshScene(box({1000.0, 1.0, 1.0}), corridor.cellM).size()), 1.25 * kCellPatchBudget);
}

TEST(Meshing, UnitSquareAtOriginIsSixteenQuads) {
  const Scene s = sceneOf({rectangleXY(0, 0, 1, 1)});
  const auto patches = meshScene(s, 0.25);
  ASSERT_EQ(patches.size(), 16u);
  EXPECT_EQ(countWithVertices(patches, 4), 16);
  for (const Patch& p : patches) {
    EXPECT_NEAR(p.areaM2, 0.0625, 1e-15);
    EXPECT_EQ(p.normal, Vec3(0, 0, 1));
    // Centroids sit at cell centres.
    EXPECT_NEAR(std::fmod(p.centroid.x, 0.25), 0.125, 1e-12);
    EXPECT_NEAR(std::fmod(p.centroid.y, 0.25), 0.125, 1e-12);
  }
  expectValidPatches(patches, 0.25, "unit square");
  expectAreaKept(s, patches, 1e-12, "unit square");
}

// 0.1 .. 0.9 crosses the lines at 0.25, 0.5 and 0.75 both ways: 4 x 4 pieces, the corner ones
// 0.15 x 0.15, the edge ones 0.15 x 0.25, the inner ones full cells.
TEST(Meshing, SquareStraddlingGridLinesCountedByHand) {
  const Scene s = sceneOf({rectangleXY(0.1, 0.1, 0.9, 0.9)});
  const auto patches = meshScene(s, 0.25);
  ASSERT_EQ(patches.size(), 16u);
  const auto areas = sortedAreas(patches);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(areas[i], 0.15 * 0.15, 1e-15);
  for (int i = 4; i < 12; ++i) EXPECT_NEAR(areas[i], 0.15 * 0.25, 1e-15);
  for (int i = 12; i < 16; ++i) EXPECT_NEAR(areas[i], 0.25 * 0.25, 1e-15);
  expectValidPatches(patches, 0.25, "straddling square");
  expectAreaKept(s, patches, 1e-12, "straddling square");

  // Only the line at 0.5 crosses 0.3 .. 0.7: four 0.2 x 0.2 quads.
  const auto small = meshScene(sceneOf({rectangleXY(0.3, 0.3, 0.7, 0.7)}), 0.25);
  ASSERT_EQ(small.size(), 4u);
  for (const Patch& p : small) EXPECT_NEAR(p.areaM2, 0.04, 1e-15);
}

// A wall facing +y (the x-z plane) and a ceiling facing down: the other dominant axes and the
// mirrored orientation.
TEST(Meshing, WallsAndDownFacingFacesKeepTheirNormals) {
  const Scene s = sceneOf({{{0, 2, 0}, {0, 2, 1.2}, {1.5, 2, 1.2}, {1.5, 2, 0}},  // faces +y
                           {{0, 0, 3}, {0, 1, 3}, {1, 1, 3}, {1, 0, 3}}});        // faces -z
  const auto patches = meshScene(s, 0.5);
  // Wall: 3 columns (0..0.5..1..1.5) x 3 rows (0..0.5..1..1.2); ceiling: 2 x 2.
  ASSERT_EQ(patches.size(), 13u);
  for (const Patch& p : patches) EXPECT_EQ(p.normal, p.polygon == 0 ? Vec3(0, 1, 0) : Vec3(0, 0, -1));
  expectValidPatches(patches, 0.5, "wall and ceiling");
  expectAreaKept(s, patches, 1e-12, "wall and ceiling");
}

// The triangle (0,0) (1,0) (0,1) on a 0.5 grid: a full cell (quad) and two half cells
// (triangles); the far cell holds only the point (0.5, 0.5), which is dropped.
TEST(Meshing, TriangleCellsAreQuadsAndTriangles) {
  const auto patches = meshScene(sceneOf({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}), 0.5);
  ASSERT_EQ(patches.size(), 3u);
  EXPECT_EQ(countWithVertices(patches, 4), 1);
  EXPECT_EQ(countWithVertices(patches, 3), 2);
  // On a 0.75 grid the first cell is the pentagon (0,0) (.75,0) (.75,.25) (.25,.75) (0,.75),
  // fanned from (0,0) into a quad and the triangle (0,0) (.25,.75) (0,.75); the other two cells
  // hold the triangles cut off at (.75,0) and (0,.75).
  const auto coarse = meshScene(sceneOf({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}), 0.75);
  ASSERT_EQ(coarse.size(), 4u);
  EXPECT_EQ(countWithVertices(coarse, 4), 1);
  const auto areas = sortedAreas(coarse);
  EXPECT_NEAR(areas[0], 0.03125, 1e-15);
  EXPECT_NEAR(areas[1], 0.03125, 1e-15);
  EXPECT_NEAR(areas[2], 0.09375, 1e-15);
  EXPECT_NEAR(areas[3], 0.75 * 0.75 - 0.125 - 0.09375, 1e-15);
  expectValidPatches(coarse, 0.75, "triangle");
}

// The same quad given from another starting vertex meshes into the same patches.
TEST(Meshing, QuadMeshesTheSameFromAnyStartingVertex) {
  const std::vector<Vec3> quad{{0.1, 0.2, 0.3}, {1.3, 0.4, 0.5}, {1.2, 1.5, 0.9}, {0.05, 1.1, 0.6}};
  const auto reference = meshScene(sceneOf({quad}), 0.381);
  for (size_t start = 1; start < 4; ++start) {
    std::vector<Vec3> rotated(quad);
    std::rotate(rotated.begin(), rotated.begin() + start, rotated.end());
    const auto patches = meshScene(sceneOf({rotated}), 0.381);
    ASSERT_EQ(patches.size(), reference.size()) << "start " << start;
    const auto a = sortedAreas(patches), b = sortedAreas(reference);
    for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-15);
    // Every patch centroid of one is a patch centroid of the other.
    for (const Patch& p : patches)
      EXPECT_TRUE(std::any_of(reference.begin(), reference.end(),
                              [&](const Patch& q) { return glm::length(q.centroid - p.centroid) < 1e-12; }));
  }
}

// A slanted polygon 1e5 m from the origin (a whole number of cells) meshes into the same
// patches, shifted, as at the origin.
// Far from the origin (site coordinates) the world grid's lines pass through the model's corner, as
// they pass through the origin a model is drawn from: the far polygon meshes as the near one moved
// so that its corner is at the origin, to rounding. Grid lines through the far origin cut it
// wherever it happened to lie.
TEST(Meshing, FarFromTheOriginMeshesLikeAtTheOrigin) {
  const std::vector<Vec3> near{
      {0.3, 0.1, 0.2}, {2.7, 0.45, 1.1}, {2.2, 1.9, 1.7}, {0.55, 2.35, 0.9}, {0.1, 1.3, 0.5}};
  Vec3 corner(INFINITY);
  for (const Vec3& v : near) corner = glm::min(corner, v);
  const Vec3 shift(1e5, -1e5, 1e5);
  std::vector<Vec3> atOrigin, far;
  for (const Vec3& v : near) atOrigin.push_back(v - corner), far.push_back(v + shift);
  const Scene sOrigin = sceneOf({atOrigin}), sFar = sceneOf({far});
  EXPECT_FALSE(gridsOf(sOrigin).world.moved());
  EXPECT_TRUE(gridsOf(sFar).world.moved());
  const auto a = meshScene(sOrigin, 0.25), b = meshScene(sFar, 0.25);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a.size(), 40u);
  for (size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].vertexCount, b[i].vertexCount) << i;
    // To 1e-9 of the polygon: far out, the input itself is only known to ~1e-11 m.
    EXPECT_NEAR(a[i].areaM2, b[i].areaM2, 1e-9 * polygonArea(near)) << i;
    EXPECT_LT(glm::length(a[i].centroid + corner + shift - b[i].centroid), 1e-9) << i;
  }
  expectValidPatches(b, 0.25, "far polygon", sFar);
  expectAreaKept(sFar, b, 1e-9, "far polygon");
}

TEST(Meshing, NoSliverFromAVertexThatRoundsOffAGridLine) {
  const Scene s = sceneOf({rectangleXY(0, 0, 0.5 + 1e-13, 0.5)});
  const auto patches = meshScene(s, 0.25);
  EXPECT_EQ(patches.size(), 4u);
  expectAreaKept(s, patches, 1e-9, "rounded square");
}

// A model moved a nanometre off the grid meshes as on it: no strip of nanometre-wide patches along
// every polygon that ends on a grid line (256 patches became 366), the edge pieces a nanometre
// larger instead. A micrometre off the grid at a 0.25 m cell is geometry, cut as before.
TEST(Meshing, AModelANanometreOffTheGridGetsNoSliverPatches) {
  for (const double offset : {1e-9, -1e-9, 3e-8}) {
    const Scene s = sceneOf({rectangleXY(offset, offset, 1 + offset, 0.5 + offset)});
    const auto patches = meshScene(s, 0.25);
    EXPECT_EQ(patches.size(), 8u) << offset;
    for (const Patch& p : patches) EXPECT_NEAR(p.areaM2, 0.0625, 1e-7) << offset;
    expectAreaKept(s, patches, 1e-12, "shifted rectangle");
  }
  EXPECT_EQ(meshScene(sceneOf({rectangleXY(1e-6, 0, 1 + 1e-6, 0.5)}), 0.25).size(), 10u);
}

TEST(Meshing, RandomConvexPolygonsKeepAreaAndShape) {
  Random r(20240501);
  for (int trial = 0; trial < 200; ++trial) {
    const int sides = 3 + static_cast<int>(r.uniform(0, 9));
    const double rx = r.uniform(0.05, 3.0), ry = r.uniform(0.05, 3.0);
    std::vector<double> angles;
    for (int i = 0; i < sides; ++i) angles.push_back(r.uniform(0, 2 * std::numbers::pi));
    std::sort(angles.begin(), angles.end());
    std::vector<Vec2> outline;
    for (double a : angles) outline.push_back({rx * std::cos(a), ry * std::sin(a)});
    if (signedArea(outline) < 1e-4 * rx * ry) continue;  // nearly collinear draw
    const Vec3 at{r.uniform(-10, 10), r.uniform(-10, 10), r.uniform(-10, 10)};
    const Scene s = sceneOf({placed(outline, randomBasis(r), at)});
    const double cell = r.uniform(0.1, 1.0);
    const auto patches = meshScene(s, cell);
    const std::string where = "convex trial " + std::to_string(trial);
    expectValidPatches(patches, cell, where, s);
    expectAreaKept(s, patches, 1e-9, where);
    if (HasFailure()) return;
  }
}

// Star-shaped polygons (a random radius at each of sorted angles) are simple and usually concave.
TEST(Meshing, RandomConcavePolygonsKeepAreaAndStayInside) {
  Random r(7);
  int concave = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int sides = 4 + static_cast<int>(r.uniform(0, 20));
    std::vector<Vec2> outline;
    for (int i = 0; i < sides; ++i) {
      const double a = 2 * std::numbers::pi * (i + r.uniform(0.1, 0.9)) / sides;
      const double radius = r.uniform(0.2, 2.5);
      outline.push_back({radius * std::cos(a), radius * std::sin(a)});
    }
    const std::vector<Vec3> polygon =
        placed(outline, randomBasis(r), {r.uniform(-5, 5), 0, r.uniform(-5, 5)});
    const Scene s = sceneOf({polygon});
    const double cell = r.uniform(0.15, 0.8);
    const auto patches = meshScene(s, cell);
    const std::string where = "concave trial " + std::to_string(trial);
    expectValidPatches(patches, cell, where, s);
    expectAreaKept(s, patches, 1e-9, where);
    for (const Patch& p : patches) ASSERT_TRUE(insidePolygon(polygon, p.centroid)) << where;
    for (size_t i = 0; i < outline.size(); ++i) {
      const Vec2 &a = outline[(i + outline.size() - 1) % outline.size()], &b = outline[i],
                 &c = outline[(i + 1) % outline.size()];
      if (cross2(b - a, c - b) < 0) {
        ++concave;
        break;
      }
    }
    if (HasFailure()) return;
  }
  EXPECT_GT(concave, 150);  // the draw really exercises the concave path
}

// An MGF-style face: a square with a square hole, reached through a zero-width seam.
TEST(Meshing, FaceWithASeamToAHole) {
  const std::vector<Vec3> face{{0, 0, 0},       {1, 0, 0},       {1, 1, 0},       {0, 1, 0},
                               {0, 0, 0},       {0.25, 0.25, 0}, {0.25, 0.75, 0}, {0.75, 0.75, 0},
                               {0.75, 0.25, 0}, {0.25, 0.25, 0}};
  const Scene s = sceneOf({face});
  ASSERT_NEAR(polygonArea(face), 0.75, 1e-15);
  const auto patches = meshScene(s, 0.25);
  expectValidPatches(patches, 0.25, "seam");
  expectAreaKept(s, patches, 1e-12, "seam");
  // The 12 cells around the hole, some split by the convex decomposition's diagonals.
  EXPECT_GE(patches.size(), 12u);
  EXPECT_LE(patches.size(), 20u);
  for (const Patch& p : patches) {
    const bool inHole =
        p.centroid.x > 0.25 && p.centroid.x < 0.75 && p.centroid.y > 0.25 && p.centroid.y < 0.75;
    EXPECT_FALSE(inHole) << "patch at " << p.centroid.x << ", " << p.centroid.y;
  }
}

// The same square listed twice round: every part is inside it twice, and both its area and its
// convex parts' count that twice, so only the winding tells. Refused, as a bow-tie is.
TEST(Meshing, AFaceThatGoesRoundTwiceIsRefused) {
  const std::vector<Vec3> twice{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<Vec3> lShapeTwice{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0},
                                      {0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  for (const auto& face : {twice, lShapeTwice}) {
    try {
      meshScene(sceneOf({face}), 0.25);
      ADD_FAILURE() << face.size() << "-vertex face accepted";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("its outline goes round part of it 2 times"), std::string::npos) << e.what();
    }
  }
}

// A comb: many reflex corners, all on grid lines, so each tooth and the spine mesh into cells.
TEST(Meshing, AxisAlignedCombOnTheGrid) {
  std::vector<Vec3> comb{{0, 0, 0}, {2, 0, 0}, {2, 0.25, 0}};
  for (double x : {1.5, 1.0, 0.5, 0.0})
    comb.insert(comb.end(), {{x + 0.25, 0.25, 0}, {x + 0.25, 1, 0}, {x, 1, 0}, {x, 0.25, 0}});
  comb.pop_back();  // the last tooth's outer side runs straight down to the start
  const Scene s = sceneOf({comb});
  const auto patches = meshScene(s, 0.25);
  expectValidPatches(patches, 0.25, "comb");
  expectAreaKept(s, patches, 1e-12, "comb");
  // Spine 8 cells + 4 teeth x 3 cells, each a full 0.25 x 0.25 square: 20 quads at best.
  const double area = polygonArea(comb);
  EXPECT_NEAR(area, 20 * 0.0625, 1e-12);
  EXPECT_GE(patches.size(), 20u);
  EXPECT_LE(patches.size(), 24u);
}

// Real MGF faces: concave outlines, holes reached through seams, many vertices.
TEST(Meshing, SharedMgfScenesMeshKeepingArea) {
  for (const char* file : {"scenes/mgf/cube.mgf", "scenes/mgf/corridor.mgf", "scenes/mgf/examp1.mgf",
                           "scenes/mgf/office2/office2.mgf", "scenes/mgf/office3/office.mgf"}) {
    RADMESH_REQUIRE_SHARED(path, file);
    const Scene s = importMgf(path.string());
    const auto patches = meshScene(s);
    expectValidPatches(patches, kDefaultCellM, file, s);
    expectAreaKept(s, patches, 1e-9, file);
  }
}

TEST(Meshing, RefusesImpossibleCells) {
  const Scene s = sceneOf({rectangleXY(0, 0, 1, 1)});
  for (double cell : {0.0, -0.381, std::nan(""), std::numeric_limits<double>::infinity()}) {
    try {
      meshScene(s, cell);
      ADD_FAILURE() << "accepted --cell " << cell;
    } catch (const OptionError& e) {
      EXPECT_NE(std::string(e.what()).find("--cell"), std::string::npos) << e.what();
    }
  }
}

TEST(Meshing, RefusesTooManyPatchesBeforeSlicing) {
  const Scene office = builtinScene("office");
  try {
    meshScene(office, 1e-9);  // ~1e20 patches: must be refused up front, not allocated
    ADD_FAILURE() << "accepted --cell 1e-9";
  } catch (const OptionError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("--cell"), std::string::npos) << message;
    EXPECT_NE(message.find("larger"), std::string::npos) << message;
  }
  const Scene square = sceneOf({rectangleXY(0, 0, 1, 1)});
  try {
    meshScene(square, 1e-300);  // too many patches to count in a double
    ADD_FAILURE() << "accepted --cell 1e-300";
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("(about 0.00141 m or more)"), std::string::npos) << e.what();
  }
  EXPECT_EQ(meshScene(square, 0.25, 16).size(), 16u);
  EXPECT_THROW(meshScene(square, 0.25, 15), OptionError);
}

// A model of more polygons than half the limit (building:100x100, 1.87 million against 2 million)
// fits only at about a patch a polygon, if at all: the refusal says so, where it suggested larger
// cells one after another that each fitted no better.
TEST(Meshing, RefusingAModelOfTooManyPolygonsSaysALargerCellResolvesNothing) {
  std::vector<std::vector<Vec3>> tiles;
  for (int i = 0; i < 100; ++i) tiles.push_back(rectangleXY(i, 0, i + 1, 1));
  const Scene s = sceneOf(tiles);
  try {
    meshScene(s, 0.5, 150);  // 400 patches
    ADD_FAILURE() << "accepted 400 patches against a limit of 150";
  } catch (const OptionError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("the cell 0.5 m would cut the scene into about 400 patches, more than the limit of 150; "
                           "its 100 polygons alone are 67 % of the limit, so no cell leaves them more than about one "
                           "patch each; solve a smaller model"),
              std::string::npos)
        << message;
  }
  // A quarter of the limit: a larger cell is the fix.
  try {
    meshScene(s, 0.5, 399);
    ADD_FAILURE() << "accepted 400 patches against a limit of 399";
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("use a larger --cell (about 0.621 m or more)"), std::string::npos) << e.what();
  }
}

// An octagon inside one cell is one cell by estimate but three quads when fanned: the limit is
// still enforced while slicing.
TEST(Meshing, RefusesTooManyPatchesWhileSlicing) {
  std::vector<Vec3> octagon;
  for (int i = 0; i < 8; ++i) {
    const double a = std::numbers::pi * i / 4;
    octagon.push_back({0.5 + 0.3 * std::cos(a), 0.5 + 0.3 * std::sin(a), 0});
  }
  const Scene s = sceneOf({octagon});
  EXPECT_EQ(meshScene(s, 1.0, 3).size(), 3u);
  EXPECT_THROW(meshScene(s, 1.0, 2), OptionError);
}

TEST(Meshing, RefusesZeroAreaAndSelfCrossingPolygons) {
  EXPECT_THROW(meshScene(sceneOf({{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}})), SceneError);
  // A figure eight with lobes of different size: its Newell area is the difference of the lobes.
  const Scene bowtie = sceneOf({{{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 1, 0}}});
  try {
    meshScene(bowtie, 0.381);
    ADD_FAILURE() << "meshed a self-crossing polygon";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("polygon 0"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace radmesh
