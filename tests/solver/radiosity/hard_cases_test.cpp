// The hard cases: each stays finite, non-negative, balanced and converging, and gives the
// answer it should.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <tuple>

#include "solver/backends/mesh/mesh_backend.h"
#include "solver/formfactors/analytic_form_factor.h"
#include "solver/io/gltf_import.h"
#include "solver/meshing/meshing.h"
#include "solver/radiosity/cell_solver.h"
#include "solver/projection/projection.h"
#include "tests/solver/closed_forms.h"
#include "tests/solver/io/gltf_test_file.h"
#include "tests/solver/solver_test_helpers.h"

namespace radmesh {
namespace {

using test::addGrid;
using test::areaMean;
using test::optionsFor;
using test::range;
using test::solveChecked;
using test::TestScene;

constexpr Projection kProjected[] = {Projection::Plane, Projection::Hemicube};

TEST(HardCases, ReflectanceOf099InAClosedRoom) {
  const TestScene box = test::closedBox({1.0, 1.3, 0.9}, 4, {test::grey(0.99), test::grey(0.99, 10.0, "light")},
                                        {0, 1, 0, 0, 0, 0});
  SolveOptions o = optionsFor(Projection::Hemicube, 32);
  o.until = 0.999;
  o.formFactorCacheBytes = size_t{256} << 20;  // tens of thousands of shots, 96 distinct rows
  ProgressiveSolver solver(box.scene, box.patches, o);
  ASSERT_TRUE(solveChecked(solver));
  EXPECT_GT(solver.history().size(), 1000u);
  // Closed and of one reflectance: B mean = emitted / ((1 - rho) area), exactly for the ambient-
  // corrected display at any iteration, and nearly for B once converged.
  const double area = 2 * (1.0 * 1.3 + 1.0 * 0.9 + 1.3 * 0.9);
  const double exact = 10.0 * 1.0 * 1.3 / ((1.0 - 0.99) * area);
  EXPECT_NEAR(areaMean(box.patches, solver.displayRadiosity()), exact, 1e-9 * exact);
  EXPECT_NEAR(areaMean(box.patches, solver.radiosity()), exact, 0.05 * exact);
  EXPECT_GT(solver.history().back().cacheHits, 0);
}

// A floor patch carries a sticker 1e-6 its area at its centroid, raised 10 micrometres.
TestScene boxWithSticker(int& sticker, int& under) {
  TestScene box = test::closedBox({1, 1, 1}, 4, {test::grey(0.5), test::grey(0.5, 10.0, "light")}, {0, 1, 0, 0, 0, 0});
  under = 6;  // a floor patch
  const double side = std::sqrt(1e-6 * box.patches[under].areaM2);
  const Vec3 c = box.patches[under].centroid + Vec3(0, 0, 1e-5);
  sticker = static_cast<int>(box.patches.size());
  box.scene.polygons.push_back({{c, c + Vec3(side, 0, 0), c + Vec3(side, side, 0)}, 0, "sticker"});
  addGrid(box.patches, c - Vec3(side / 2, side / 2, 0), {side, 0, 0}, {0, side, 0}, 1, 1, 0, 6);
  return box;
}

TEST(HardCases, PatchAMillionthTheAreaOfItsNeighbour) {
  int sticker = 0, under = 0;
  const TestScene box = boxWithSticker(sticker, under);
  EXPECT_NEAR(box.patches[sticker].areaM2 / box.patches[under].areaM2, 1e-6, 1e-12);
  for (Projection p : kProjected) {
    for (bool refine : {true, false}) {
      SolveOptions o = optionsFor(p, 64);
      o.until = 0.99;
      o.subPixelReceivers = refine;
      ProgressiveSolver solver(box.scene, box.patches, o);
      ASSERT_TRUE(solveChecked(solver)) << toString(p);
      // It sits where its neighbour's centroid is: it should be as bright.
      const double b = solver.radiosity()[sticker].r, neighbour = solver.radiosity()[under].r;
      if (refine) {
        EXPECT_NEAR(b, neighbour, 0.05 * neighbour) << toString(p);
      } else {  // pixel centres alone miss it or give it a whole pixel: the paper's aliasing
        EXPECT_GT(std::abs(b - neighbour), 0.5 * neighbour) << toString(p);
      }
    }
  }
}

// A unit-square shooter (cut into 8 x 8 points) and a unit square hinged to it along x = 0,
// opened to `degrees` (90: a wall; 10: nearly closed over it).
TestScene hinge(double degrees) {
  TestScene t;
  t.scene.source = "hinge";
  t.scene.materials = {test::grey(0.5, 1.0)};
  const double a = degrees * std::numbers::pi / 180.0;
  addGrid(t.patches, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 8, 8);
  addGrid(t.patches, {0, 0, 0}, {0, 1, 0}, {std::cos(a), 0, std::sin(a)}, 1, 1);
  return t;
}

TEST(HardCases, PatchesMeetingTheShooterAtASharedEdgeAt90And10Degrees) {
  for (double degrees : {90.0, 10.0}) {
    const TestScene t = hinge(degrees);
    const auto shooters = range(0, 64);
    const double oracle = test::areaFormFactor(t, optionsFor(Projection::Analytic), shooters, {64});
    double previous = 1.0;
    for (int n : {32, 128, 512}) {
      const double error = std::abs(test::areaFormFactor(t, optionsFor(Projection::Hemicube, n), shooters, {64}) - oracle);
      EXPECT_LT(error, previous) << degrees << " degrees, N = " << n;
      previous = error;
    }
    EXPECT_LT(previous, 0.005 * oracle) << degrees << " degrees";
    // Solving: the hinge is open, so some light escapes; everything stays balanced.
    for (Projection p : kProjected) {
      SolveOptions o = optionsFor(p, 64);
      o.until = 0.999;
      ProgressiveSolver solver(t.scene, t.patches, o);
      ASSERT_TRUE(solveChecked(solver)) << degrees << " " << toString(p);
      EXPECT_GT(solver.ledger().escaped, 0.0);
    }
  }
  EXPECT_GT(test::areaFormFactor(hinge(10.0), optionsFor(Projection::Analytic), range(0, 64), {64}), 0.8);
}

TEST(HardCases, SliverTrianglesOfAspect1e4) {
  // An emitter under a unit square 1 m up whose first centimetre is 100 slivers of 1 m x 0.1 mm,
  // each cut into two triangles.
  TestScene t;
  t.scene.source = "slivers";
  t.scene.materials = {test::grey(0.5, 1.0), test::grey(0.5)};
  addGrid(t.patches, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1, 1, 0);
  for (int k = 0; k < 100; ++k) {
    const double y0 = k * 1e-4, y1 = (k + 1) * 1e-4;
    t.patches.push_back(test::makePatch({{0, y0, 1}, {1, y1, 1}, {1, y0, 1}}, 1));
    t.patches.push_back(test::makePatch({{0, y0, 1}, {0, y1, 1}, {1, y1, 1}}, 1));
  }
  addGrid(t.patches, {0, 0.01, 1}, {0, 0.99, 0}, {1, 0, 0}, 1, 1, 1);
  const double band = pointToPolygonFormFactor(std::vector<Vec3>{{-0.5, -0.5, 1}, {0.5, -0.5, 1}, {0.5, -0.49, 1}, {-0.5, -0.49, 1}});
  const double whole = pointToPolygonFormFactor(std::vector<Vec3>{{-0.5, -0.5, 1}, {0.5, -0.5, 1}, {0.5, 0.5, 1}, {-0.5, 0.5, 1}});
  for (Projection p : kProjected) {
    const FormFactorRow row = test::rowsOf(t, optionsFor(p, 256), {0})[0];
    double slivers = 0.0;
    for (int j = 1; j <= 200; ++j) slivers += test::entry(row, j);
    EXPECT_NEAR(row.hitFraction(), whole, 0.03 * whole) << toString(p);  // a pixel row of its edge
    EXPECT_NEAR(slivers, band, 0.05 * band) << toString(p);
    SolveOptions o = optionsFor(p, 256);
    o.until = 0.999;
    ProgressiveSolver solver(t.scene, t.patches, o);
    ASSERT_TRUE(solveChecked(solver)) << toString(p);
  }
}

// A ceiling light 1.5 m from a wall that a grid line and a door's top cut into a 0.1 m strip
// (building:1x1 at --cell 1): the strip is 2 to 3.2 pixels tall on the hemicube's side face at
// these resolutions, and whether a row of pixel centres more or less falls in it moves with the
// resolution. Pixel sums alone were 7 % low for this light at 96², and in the whole solve the
// strip's elements a fifth dark at 95² and 96², alike along the whole wall: a dark line.
TEST(HardCases, AStripAFewPixelsTallGetsItsFormFactorAtAnyResolution) {
  TestScene t;
  t.scene.source = "strip";
  t.scene.materials = {test::grey(0.5, 1.0), test::grey(0.5)};
  addGrid(t.patches, {-0.3, 1.2, 2.7}, {0, 0.6, 0}, {0.6, 0, 0}, 1, 1, 0);  // facing down
  for (const auto& [z0, z1] : {std::pair{1.0, 2.0}, {2.0, 2.1}, {2.1, 2.7}})  // facing the light
    addGrid(t.patches, {-0.5, 0, z0}, {0, 0, z1 - z0}, {1, 0, 0}, 1, 1, 1);
  const int strip = 2;
  const double exact = pointToPolygonFormFactor(toShooterFrame(t.patches[0], t.patches[strip]).corners());
  for (int n : {64, 80, 95, 96, 97}) {
    const FormFactorRow row = test::rowsOf(t, optionsFor(Projection::Hemicube, n), {0})[0];
    EXPECT_NEAR(test::entry(row, strip), exact, 0.02 * exact) << "N = " << n;
  }
}

// A shelf 5 mm thick under a ceiling light in front of it: its edge face, cut in four, covers no
// pixel centre at most of these resolutions, and the pixel its centroid falls in shows the shelf's
// top, whose plane passes in front of the edge face beyond their common edge. That plane was taken
// for the top itself: the edge face hidden, 52 % dark at 64² and 13 % at 256² in a whole solve.
TEST(HardCases, AThinEdgeFaceOfASolidIsNotHiddenByItsNeighboursPlane) {
  TestScene t;
  t.scene.source = "shelf";
  t.scene.materials = {test::grey(0.5, 1.0), test::grey(0.5)};
  addGrid(t.patches, {3.2, 1.4, 2.49}, {0, 0.2, 0}, {0.2, 0, 0}, 1, 1, 0, 0);      // the light, facing down
  addGrid(t.patches, {1.5, 1, 1.005}, {1, 0, 0}, {0, 1, 0}, 1, 1, 1, 1);           // top
  addGrid(t.patches, {2.5, 1, 1}, {0, 1, 0}, {0, 0, 0.005}, 4, 1, 1, 2);           // edge face, facing +x
  addGrid(t.patches, {1.5, 1, 1}, {0, 1, 0}, {1, 0, 0}, 1, 1, 1, 3);               // bottom
  for (int n : {64, 96, 128, 256}) {
    const FormFactorRow row = test::rowsOf(t, optionsFor(Projection::Hemicube, n), {0})[0];
    for (int j = 2; j < 6; ++j) {
      const double exact = pointToPolygonFormFactor(toShooterFrame(t.patches[0], t.patches[j]).corners());
      EXPECT_NEAR(test::entry(row, j), exact, 0.03 * exact) << "N = " << n << ", edge patch " << j - 2;
    }
  }
}

// An asymmetric room: one light patch off-centre in the ceiling, walls of two reflectances. Its
// sizes are not round numbers: with round ones, edges pass exactly through pixel centres, where
// the fill rule decides and a rounding-sized shift may hand the pixel to the neighbour.
TestScene room(Vec3 offset) {
  TestScene t = test::closedBox({1.0137, 1.2911, 0.8763}, 4, {test::grey(0.6), test::grey(0.3), test::grey(0.2, 10.0, "light")},
                                {0, 0, 1, 0, 1, 0}, offset);
  t.patches[16 + 5].material = 2;
  return t;
}

TEST(HardCases, SceneOffset1e5MetresGivesTheSameRadiosity) {
  const TestScene near = room(Vec3(0.0)), far = room(Vec3(1e5, 1e5, 1e5));
  for (Projection p : {Projection::Plane, Projection::Hemicube, Projection::Analytic}) {
    std::vector<Rgb> b[2];
    for (int k = 0; k < 2; ++k) {
      const SolveOptions o = test::fixedIterations(optionsFor(p, 128), 100);
      ProgressiveSolver solver(k ? far.scene : near.scene, k ? far.patches : near.patches, o);
      solveChecked(solver);
      b[k] = solver.radiosity();
    }
    const double mean = areaMean(near.patches, b[0]);
    for (size_t j = 0; j < b[0].size(); ++j)
      EXPECT_NEAR(b[1][j].r, b[0][j].r, 1e-4 * std::max(b[0][j].r, mean)) << toString(p) << " patch " << j;
  }
}

// A room lit by its ceiling with a block on the floor, moved by `shift` and meshed at the paper's
// 15 inches: the grid line x = 1.905 cuts the floor a quarter of a cell short of the block's side
// x = 2, and the side's cells are the floor's size. Returns the first of the block's polygons.
int roomWithABlock(Vec3 shift, TestScene& t) {
  t = test::closedBox({4, 3, 2.5}, 1, {test::grey(0.6), test::grey(0.0, 10.0, "light")}, {0, 1, 0, 0, 0, 0}, shift);
  const int block = static_cast<int>(t.scene.polygons.size());
  const Vec3 low = shift + Vec3(1, 1, 0), high = shift + Vec3(2, 1.8, 0.8);
  const Vec3 x(1, 0, 0), y(0, 0.8, 0), z(0, 0, 0.8);
  for (const auto& [corner, u, v] : {std::tuple{Vec3(low.x, low.y, high.z), x, y}, {low, z, y}, {low, x, z},
                                     {Vec3(high.x, low.y, low.z), y, z}, {Vec3(low.x, high.y, low.z), z, x}})
    test::addPolygon(t.scene, corner, u, v, 0);  // outward: top, x = 1, y = 1, x = 2, y = 1.8
  t.patches = meshScene(t.scene, kDefaultCellM);
  return block;
}

// The floor cell beside the block's side, a quarter of it under the block, was sampled from itself
// in the near field when rounding made the side's diameter no smaller than the cell's, and its
// quarter under the block, which sees the side's back, counted as lighting the side's front: a
// shift of 1e-12 m moved the side's lowest patch by 7 %.
TEST(HardCases, ARoomMovedBy1e12MetresGivesItsBlockTheSameRadiosity) {
  std::vector<Rgb> b[2];
  TestScene t[2];
  int block = 0;
  for (int k = 0; k < 2; ++k) {
    block = roomWithABlock(Vec3(0, 0, k ? 1e-12 : 0.0), t[k]);
    SolveOptions o = optionsFor(Projection::Hemicube, 64);
    o.untilUnshot = 1e-4;
    ProgressiveSolver solver(t[k].scene, t[k].patches, o);
    ASSERT_TRUE(solveChecked(solver));
    b[k] = solver.radiosity();
  }
  ASSERT_EQ(t[0].patches.size(), t[1].patches.size());
  int blockPatches = 0;
  for (size_t j = 0; j < b[0].size(); ++j)
    if (t[0].patches[j].polygon >= block) {
      ++blockPatches;
      EXPECT_NEAR(b[1][j].r, b[0][j].r, 0.005 * b[0][j].r) << "patch " << j << " at " << t[0].patches[j].centroid.x
                                                            << ", " << t[0].patches[j].centroid.y << ", "
                                                            << t[0].patches[j].centroid.z;
    }
  EXPECT_GT(blockPatches, 20);
}

// Two closed 4 x 3 x 2.5 m rooms of 8 x 8 patches a face, the second `gap` metres beyond the first
// along x (0: each with its own side of the wall between them, in one plane); their faces'
// materials as closedBox takes them. The first room's patches come first: kRoomPatches of them.
constexpr int kRoomPatches = 6 * 64;
TestScene twoRooms(const std::vector<Material>& materials, double gap, std::array<int, 6> first = {},
                   std::array<int, 6> second = {}) {
  TestScene rooms = test::closedBox({4, 3, 2.5}, 8, materials, first);
  const TestScene other = test::closedBox({4, 3, 2.5}, 8, materials, second, Vec3(4 + gap, 0, 0));
  const int polygons = static_cast<int>(rooms.scene.polygons.size());
  rooms.scene.polygons.insert(rooms.scene.polygons.end(), other.scene.polygons.begin(), other.scene.polygons.end());
  for (Patch p : other.patches) {
    p.polygon += polygons;
    rooms.patches.push_back(p);
  }
  return rooms;
}

// Two closed rooms side by side, one lit, parted by a wall of no thickness, their outer walls in
// line. A patch in the dark room too small to cover a pixel centre was seen past the dividing wall
// where its centroid's pixel showed the lit room's wall in the same plane, which hid nothing:
// 3.5 % of the lit room's light in the dark one at 16², less at higher resolutions.
TEST(HardCases, NoLightReachesARoomSealedBehindAWallOfNoThickness) {
  const std::vector<Material> materials = {test::grey(0.7), test::grey(0.0, 30.0, "light")};
  TestScene rooms = twoRooms(materials, 0.0);
  const size_t litPatches = kRoomPatches;
  rooms.patches[64 + 27].material = 1;  // a lamp in the lit room's ceiling
  for (const auto& [projection, n] : {std::pair{Projection::Hemicube, 16}, {Projection::Hemicube, 32}, {Projection::Plane, 32}}) {
    SolveOptions o = optionsFor(projection, n);
    o.until = 1.0;
    o.untilUnshot = 0.05;
    ProgressiveSolver solver(rooms.scene, rooms.patches, o);
    ASSERT_TRUE(solveChecked(solver));
    double lit = 0.0;
    for (size_t j = 0; j < rooms.patches.size(); ++j) {
      if (j < litPatches) lit = std::max(lit, solver.radiosity()[j].r);
      else EXPECT_EQ(solver.radiosity()[j].r, 0.0) << toString(projection) << " " << n << "², dark patch " << j;
    }
    EXPECT_GT(lit, 0.1);
  }
}

// Two closed rooms, each a box with its own lamp, sharing the plane of a wall of no thickness: each
// room's side of it faces that room. The two sides tie at every pixel; the geometric tie rank gave
// both lamps the same side, so one room's side of the wall stayed black.
TEST(HardCases, BothSidesOfAWallOfNoThicknessAreLit) {
  const std::vector<Material> materials = {test::grey(0.7), test::grey(0.0, 30.0, "light")};
  TestScene rooms = twoRooms(materials, 0.0);
  const int perRoom = kRoomPatches;
  rooms.patches[64 + 27].material = 1;
  rooms.patches[perRoom + 64 + 27].material = 1;
  const int leftSide = 3 * 64, rightSide = perRoom + 2 * 64;  // x = 4 facing -x, and facing +x
  for (Backend backend : {Backend::Native, Backend::Mesh}) {
    SolveOptions o = optionsFor(Projection::Hemicube, 32);
    if (backend == Backend::Mesh) o = optionsFor(Projection::Plane, 32);
    o.backend = backend;
    o.maxIterations = 2;  // the lamps
    ProgressiveSolver solver(rooms.scene, rooms.patches, o);
    ASSERT_TRUE(solveChecked(solver));
    // The mesh's single plane misses the grazing directions to a side's far patches: 16 and 8 of
    // them (before, 16 and 56).
    const int least = backend == Backend::Native ? 64 : 48;
    for (int side : {leftSide, rightSide}) {
      int lit = 0;
      for (int k = 0; k < 64; ++k) lit += solver.radiosity()[side + k].r > 0.0;
      EXPECT_GE(lit, least) << toString(backend) << ", the wall's side from patch " << side;
    }
  }
}

// Two closed rooms side by side, 0.2 m apart, each lit by its whole ceiling, one a thousand times
// dimmer: a tenth of a percent of the power, in 64 patches. The unshot stop (1 %) was met while
// the bright room's patches still outshone each of the dim ceiling's, which never shot: its room
// stayed black in a whole solve (and in cells, in a numerical audit's scene, lit only a little).
TEST(HardCases, ADimRoomsLampShootsBeforeTheUnshotStop) {
  const std::vector<Material> materials = {test::grey(0.7), test::grey(0.0, 30.0, "light"),
                                           test::grey(0.0, 0.03, "dim light")};
  const TestScene rooms = twoRooms(materials, 0.2, {0, 1, 0, 0, 0, 0}, {0, 2, 0, 0, 0, 0});
  const size_t litPatches = kRoomPatches;
  SolveOptions o = optionsFor(Projection::Hemicube, 32);
  o.until = 1.0;
  o.untilUnshot = 0.01;
  // Below the dim room's ceiling, every patch sees it.
  auto expectDimRoomLit = [&](const std::vector<Rgb>& b, const char* solve) {
    for (size_t j = litPatches; j < rooms.patches.size(); ++j)
      if (rooms.patches[j].centroid.z < 2.5 - 1e-9) {
        EXPECT_GT(b[j].r, 0.0) << solve << ", dim room patch " << j;
      }
  };
  ProgressiveSolver whole(rooms.scene, rooms.patches, o);
  ASSERT_TRUE(solveChecked(whole));
  EXPECT_EQ(whole.emittersToShoot(), 0);
  expectDimRoomLit(whole.radiosity(), "whole");

  // On the mesh back end the machine picks those shots too, by its reduceMax over their power: every
  // iteration is charged for its shooter selection (the host had picked them uncharged).
  SolveOptions onMesh = o;
  onMesh.backend = Backend::Mesh;
  onMesh.projection = Projection::Plane;
  onMesh.resolution = 64;
  onMesh.shooters = 4;
  onMesh.untilUnshot = 0.9;  // under it after a few shots: the waiting emitters are most of the solve
  ProgressiveSolver mesh(rooms.scene, rooms.patches, onMesh);
  int waitingShots = 0;
  while (!mesh.done()) {
    waitingShots += mesh.ledger().unshotFraction() <= onMesh.untilUnshot;
    const IterationRecord& record = mesh.step();
    const std::vector<MeshPhaseCost>& phases = dynamic_cast<MeshBackend&>(mesh.backend()).lastShot().phases;
    ASSERT_FALSE(phases.empty()) << "iteration " << record.iteration;
    EXPECT_EQ(phases.front().name, "shooter selection") << "iteration " << record.iteration;
  }
  EXPECT_EQ(mesh.emittersToShoot(), 0);
  EXPECT_GE(waitingShots, 20);  // the 128 ceiling patches less the few shot first, four at a time

  CellPartition partition;
  partition.cells = {{"lit", {0, 0, 0}, {4, 3, 2.5}}, {"dim", {4.2, 0, 0}, {8.2, 3, 2.5}}};
  for (size_t j = 0; j < rooms.patches.size(); ++j) partition.cellOfPatch.push_back(j < litPatches ? 0 : 1);
  CellSolver cells(rooms.scene, rooms.patches, partition, o, {kDefaultCellM, 8});
  for (int round = 0; !cells.done() && round < 1000; ++round) cells.round();
  ASSERT_TRUE(cells.done());
  expectDimRoomLit(cells.radiosity(), "cells");
}

TEST(HardCases, CoplanarOverlappingPatchesGiveAnOrderIndependentAnswer) {
  // Two posters on the wall x = 0, in its very plane, overlapping the wall and each other.
  TestScene t = room(Vec3(0.0));
  t.scene.materials.push_back({"red", Rgb(0.7, 0.1, 0.1), Rgb(0.0)});
  addGrid(t.patches, {0, 0.2, 0.2}, {0, 0.5, 0}, {0, 0, 0.4}, 1, 1, 3, 2);
  addGrid(t.patches, {0, 0.4, 0.3}, {0, 0.5, 0}, {0, 0, 0.4}, 1, 1, 3, 2);
  TestScene reversed = t;
  std::reverse(reversed.patches.begin(), reversed.patches.end());
  const size_t n = t.patches.size();
  for (Projection p : kProjected) {
    const SolveOptions o = test::fixedIterations(optionsFor(p, 128), 100);
    ProgressiveSolver a(t.scene, t.patches, o), b(reversed.scene, reversed.patches, o);
    solveChecked(a);
    solveChecked(b);
    for (size_t j = 0; j < n; ++j)
      EXPECT_NEAR(a.radiosity()[j].r, b.radiosity()[n - 1 - j].r, 1e-9 * (1 + a.radiosity()[j].r)) << toString(p) << " " << j;
    // The poster that wins its overlap gets light; whichever it is, it is the same one both ways.
    EXPECT_GT(a.radiosity()[n - 1].r + a.radiosity()[n - 2].r, 0.0);
  }
}

TEST(HardCases, EmitterFacingAwayFromEverything) {
  TestScene t = test::closedBox({1, 1, 1}, 2, {test::grey(0.5), test::grey(0.5, 5.0, "light")});
  addGrid(t.patches, {0.2, 0.2, 1.5}, {0.6, 0, 0}, {0, 0.6, 0}, 1, 1, 1, 5);  // above the box, facing up
  for (Projection p : {Projection::Plane, Projection::Hemicube, Projection::Analytic}) {
    ProgressiveSolver solver(t.scene, t.patches, optionsFor(p, 64));
    ASSERT_TRUE(solveChecked(solver));
    EXPECT_EQ(solver.history().size(), 1u);
    EXPECT_EQ(solver.convergence(), 1.0);  // nothing is left to shoot
    const Ledger& l = solver.ledger();
    const double captured = p == Projection::Plane ? solver.projectionSummary().capturedFraction : 1.0;
    EXPECT_NEAR(l.escaped, l.emitted * captured, 1e-12 * l.emitted);
    EXPECT_NEAR(l.notCaptured, l.emitted * (1 - captured), 1e-12 * l.emitted);
    for (size_t j = 0; j + 1 < t.patches.size(); ++j) EXPECT_EQ(solver.radiosity()[j], Rgb(0.0));
  }
}

TEST(HardCases, PatchEntirelyBehindTheShooter) {
  TestScene t;
  t.scene.source = "behind";
  t.scene.materials = {test::grey(0.0, 1.0, "light"), test::grey(0.5), test::grey(0.0, 0.0, "black")};
  addGrid(t.patches, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1, 1, 0);    // the light, facing up
  addGrid(t.patches, {0, 0, 1}, {0, 1, 0}, {1, 0, 0}, 1, 1, 1);    // above, facing down at it
  addGrid(t.patches, {0, 0, -1}, {1, 0, 0}, {0, 1, 0}, 1, 1, 2);   // below, facing its back
  addGrid(t.patches, {0, 0, -0.5}, {0, 1, 0}, {1, 0, 0}, 1, 1, 2);  // below, facing away
  for (Projection p : {Projection::Plane, Projection::Hemicube, Projection::Analytic}) {
    const FormFactorRow row = test::rowsOf(t, optionsFor(p, 128), {0})[0];
    EXPECT_EQ(row.receivers, std::vector<int>{1}) << toString(p);
    EXPECT_EQ(row.backFaces, 0.0);
    ProgressiveSolver solver(t.scene, t.patches, optionsFor(p, 128));
    ASSERT_TRUE(solveChecked(solver));
    EXPECT_GT(solver.radiosity()[1].r, 0.0);
    EXPECT_GT(solver.ledger().escaped, 0.0);
  }
}

TEST(HardCases, PatchStraddlingTheShootersPlaneCountsOnlyItsFrontPart) {
  // A wall at x = 2 from z = -1 to 1: only its upper half is in front of the shooter.
  TestScene t;
  t.scene.source = "straddling";
  t.scene.materials = {test::grey(0.5, 1.0)};
  addGrid(t.patches, {-0.01, -0.01, 0}, {0.02, 0, 0}, {0, 0.02, 0}, 1, 1);
  addGrid(t.patches, {2, -1, -1}, {0, 0, 2}, {0, 2, 0}, 1, 1);  // facing -x
  const double upper = pointToPolygonFormFactor(std::vector<Vec3>{{2, -1, 0}, {2, 1, 0}, {2, 1, 1}, {2, -1, 1}});
  EXPECT_NEAR(test::entry(test::rowsOf(t, optionsFor(Projection::Analytic), {0})[0], 1), upper, 1e-6 * upper);
  EXPECT_NEAR(test::entry(test::rowsOf(t, optionsFor(Projection::Hemicube, 512), {0})[0], 1), upper, 0.01 * upper);
}

// A glTF card marked doubleSided, 1 above a square lamp facing it: its underside receives the
// lamp's light (a one-sided card would absorb it on its unlit back), its top none.
TEST(HardCases, DoubleSidedCardReceivesOnItsUnderside) {
  test::TempDir dir;
  test::GltfBuilder b;
  const nlohmann::json grey = {{"baseColorFactor", {0.5, 0.5, 0.5, 1.0}}};
  b.add("materials", {{"name", "lamp"}, {"pbrMetallicRoughness", grey}, {"emissiveFactor", {1.0, 1.0, 1.0}},
                      {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 10.0}}}}}});
  b.add("materials", {{"name", "card"}, {"pbrMetallicRoughness", grey}, {"doubleSided", true}});
  const auto square = [](double z) { return std::vector<Vec3>{{0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 0, z}, {1, 1, z}, {0, 1, z}}; };
  b.addTriangles("lamp", b.addPositions(square(0.0)), -1, 0);
  b.addTriangles("card", b.addPositions(square(1.0)), -1, 1);
  TestScene t;
  t.scene = importGltf(b.write(dir / "card.gltf").string());
  t.patches = meshScene(t.scene, 0.125);
  ASSERT_EQ(t.patches.size(), 3u * 64u);
  ProgressiveSolver solver(t.scene, t.patches, test::fixedIterations(optionsFor(Projection::Hemicube, 128), 64));
  solveChecked(solver);
  ASSERT_EQ(solver.history().size(), 64u);
  std::vector<Patch> under, top;
  std::vector<Rgb> underB, topB;
  for (size_t i = 0; i < t.patches.size(); ++i) {
    if (t.patches[i].material != 1) continue;
    (t.patches[i].normal.z < 0 ? under : top).push_back(t.patches[i]);
    (t.patches[i].normal.z < 0 ? underB : topB).push_back(solver.radiosity()[i]);
  }
  ASSERT_EQ(under.size(), 64u);
  // Every lamp patch has shot once: B = rho E F(lamp -> card), the facing unit squares' form factor.
  const double expected = 0.5 * 10.0 * test::parallelRectanglesFormFactor(1.0, 1.0, 1.0);
  EXPECT_NEAR(areaMean(under, underB), expected, 0.02 * expected);
  EXPECT_EQ(areaMean(top, topB), 0.0);
}

}  // namespace
}  // namespace radmesh
