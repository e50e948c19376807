// A cells solve whose patches are cut into elements (--cells auto --subdivide uniform|adaptive):
// patches shoot, elements receive, in each cell; portal patches pass power on per patch.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/io/builtin_scenes.h"
#include "solver/meshing/elements.h"
#include "solver/meshing/meshing.h"
#include "solver/radiosity/cell_solver.h"
#include "tests/solver/radiosity/two_rooms_cells.h"
#include "tests/solver/solver_test_helpers.h"

namespace radmesh {
namespace {

// two-rooms at the 0.75 m grid (374 patches): room A lit, room B lit only through the door.
constexpr double kCellM = 0.75;
using test::reflectedInRoom;
using test::TwoRooms;
using test::twoRoomsPartition;

SolveOptions elementOptions(Subdivide how, double untilUnshot, int threads = 1) {
  SolveOptions o;
  o.projection = Projection::Hemicube;
  o.resolution = 32;
  o.until = 1.0;
  o.untilUnshot = untilUnshot;
  o.threads = threads;
  return test::subdivided(o, how, how == Subdivide::Adaptive ? 0.2 : 0.0);
}

TwoRooms twoRoomsAtTheCell() {
  Scene scene = builtinScene("two-rooms");
  return {scene, meshScene(scene, kCellM)};
}

// Each cell's ledger and the building's balance every round, with uniform and adaptive elements;
// the building's elements tile its patches (each polygon's elements adding up to its patches' area),
// and the cells' element counts add up to them.
TEST(CellElements, LedgerBalancesAndElementsTileThePatches) {
  const TwoRooms t = twoRoomsAtTheCell();
  for (Subdivide how : {Subdivide::Uniform, Subdivide::Adaptive}) {
    CellSolver solver(t.scene, t.patches, twoRoomsPartition(t.patches), elementOptions(how, 0.05), {kCellM, 16, 4});
    int rounds = 0;
    for (; !solver.done() && rounds < 500; ++rounds) {
      solver.round();
      EXPECT_LE(solver.ledger().imbalance(), 1e-9) << toString(how) << ", round " << rounds;
      for (const CellFigures& cell : solver.cellFigures())
        EXPECT_LE(cell.ledger.imbalance(), 1e-9) << toString(how) << ", " << cell.name << ", round " << rounds;
    }
    ASSERT_TRUE(solver.done());
    EXPECT_LE(solver.ledger().unshotFraction(), 0.05);
    const std::vector<CellFigures> cells = solver.cellFigures();
    EXPECT_GT(cells[1].ledger.portalIn, 0.0);  // light reached B through the door
    const std::vector<Patch> elements = solver.elements().elements;
    ASSERT_EQ(static_cast<int>(elements.size()), cells[0].elements + cells[1].elements);
    if (how == Subdivide::Uniform) EXPECT_EQ(elements.size(), 4 * t.patches.size());
    else EXPECT_GT(elements.size(), t.patches.size());
    ASSERT_EQ(solver.elementRadiosity().size(), elements.size());
    std::vector<double> patchArea(t.scene.polygons.size(), 0.0), elementArea(t.scene.polygons.size(), 0.0);
    for (const Patch& p : t.patches) patchArea[p.polygon] += p.areaM2;
    for (const Patch& e : elements) elementArea[e.polygon] += e.areaM2;
    for (size_t k = 0; k < patchArea.size(); ++k)
      EXPECT_NEAR(elementArea[k], patchArea[k], 1e-12 * patchArea[k]) << "polygon " << k;
  }
}

// With uniform elements the cells solve makes the elements the whole solve does, in the building's
// order, and a light without a patch lands on them bitwise as the whole solve's first iteration.
TEST(CellElements, UniformElementsAndTheLightsShotAreTheWholeSolves) {
  TwoRooms t = twoRoomsAtTheCell();
  for (Material& m : t.scene.materials) m.emittance = Rgb(0.0);
  t.scene.lights.push_back({"lamp", LightType::Point, {2.0, 2.0, 2.2}, {0, 0, -1}, Rgb(2.0)});
  const SolveOptions o = elementOptions(Subdivide::Uniform, 0.05);
  CellSolver cells(t.scene, t.patches, twoRoomsPartition(t.patches), o, {kCellM, 16, 4});
  ProgressiveSolver whole(t.scene, t.patches, o);
  whole.step();  // the light's shot
  const std::vector<Patch> elements = cells.elements().elements;
  ASSERT_EQ(elements.size(), whole.elements().size());
  for (size_t e = 0; e < elements.size(); ++e) {
    ASSERT_EQ(elements[e].vertices, whole.elements()[e].vertices) << "element " << e;
    ASSERT_EQ(elements[e].areaM2, whole.elements()[e].areaM2) << "element " << e;
  }
  EXPECT_EQ(cells.elementRadiosity(), whole.elementRadiosity());
  EXPECT_EQ(cells.radiosity(), whole.radiosity());
  EXPECT_NEAR(cells.ledger().unshot, whole.ledger().unshot, 1e-12 * cells.ledger().emitted);
  for (; !cells.done(); cells.round()) EXPECT_LE(cells.ledger().imbalance(), 1e-9);
}

// With adaptive elements a light without a patch splits the elements where its direct light
// changes before the first round, and the children take that light anew, shot over the building,
// as the whole solve's first iteration splits and regathers (before, the cell wrote past the end
// of its gains and crashed). The building as one cell: bitwise the whole solve's elements and
// light. As two rooms: room B's elements split where light through the door falls, and every
// round balances.
TEST(CellElements, AdaptiveElementsSplitWhereALightChangesAsInTheWholeSolvesFirstIteration) {
  TwoRooms t = twoRoomsAtTheCell();
  for (Material& m : t.scene.materials) m.emittance = Rgb(0.0);
  t.scene.lights.push_back({"lamp", LightType::Point, {2.0, 2.0, 2.2}, {0, 0, -1}, Rgb(2.0)});
  const SolveOptions o = elementOptions(Subdivide::Adaptive, 0.05);
  CellPartition one;
  one.cells.push_back({"building", Vec3(-100.0), Vec3(100.0)});
  one.cellOfPatch.assign(t.patches.size(), 0);
  CellSolver cells(t.scene, t.patches, one, o, {kCellM, 16, 4});
  ProgressiveSolver whole(t.scene, t.patches, o);
  const int split = whole.step().elementsSplit;  // the light's shot, then its splits
  ASSERT_GT(split, 0);
  const std::vector<Patch> elements = cells.elements().elements;
  ASSERT_EQ(elements.size(), whole.elements().size());
  for (size_t e = 0; e < elements.size(); ++e) ASSERT_EQ(elements[e].vertices, whole.elements()[e].vertices) << "element " << e;
  EXPECT_EQ(cells.elementRadiosity(), whole.elementRadiosity());
  cells.round();
  EXPECT_GE(cells.cellSolver(0).history().front().elementsSplit, split);  // the cell's first iteration counts them

  CellSolver rooms(t.scene, t.patches, twoRoomsPartition(t.patches), o, {kCellM, 16, 4});
  const std::vector<CellFigures> before = rooms.cellFigures();
  EXPECT_GT(before[0].elements, before[0].patches);
  EXPECT_GT(before[1].elements, before[1].patches);
  for (int round = 0; !rooms.done() && round < 500; ++round) {
    rooms.round();
    EXPECT_LE(rooms.ledger().imbalance(), 1e-9) << "round " << round;
  }
  EXPECT_TRUE(rooms.done());
}

// Each room's reflected light against the whole building's uniform solve, both to 1 % unshot on
// the same elements, 4 x 4 portal bins. Measured: room A 0.37 %, room B 5.1 % off (the patches'
// solve: B +5.8 % at this grid, docs/cells.md); the tolerances leave a margin.
TEST(CellElements, UniformLightPerRoomNearTheWholeBuildingUniformSolve) {
  const TwoRooms t = twoRoomsAtTheCell();
  SolveOptions o = elementOptions(Subdivide::Uniform, 0.01);
  o.effects = EffectsMode::All;
  CellSolver cells(t.scene, t.patches, twoRoomsPartition(t.patches), o, {kCellM, 16, 4});
  while (!cells.done()) cells.round();
  ProgressiveSolver whole(t.scene, t.patches, o);
  while (!whole.done()) whole.step();
  const std::vector<Patch> elements = cells.elements().elements;
  const std::vector<Rgb> b = cells.elementRadiosity();
  const double roomA = reflectedInRoom(t.scene, elements, b, true) / reflectedInRoom(t.scene, whole.elements(), whole.elementRadiosity(), true) - 1.0;
  const double roomB = reflectedInRoom(t.scene, elements, b, false) / reflectedInRoom(t.scene, whole.elements(), whole.elementRadiosity(), false) - 1.0;
  EXPECT_LT(std::abs(roomA), 0.006) << roomA;
  EXPECT_LT(std::abs(roomB), 0.08) << roomB;
}

// Splits in a cell touch its elements alone: in the first round only room A shoots, and its
// elements split while B's stay its patches; B's split once light through the door reaches them.
TEST(CellElements, AdaptiveSplitsOnlyTheShootingCellsElements) {
  const TwoRooms t = twoRoomsAtTheCell();
  CellSolver solver(t.scene, t.patches, twoRoomsPartition(t.patches), elementOptions(Subdivide::Adaptive, 0.05),
                    {kCellM, 16, 4});
  solver.round();
  std::vector<CellFigures> cells = solver.cellFigures();
  EXPECT_EQ(cells[1].iterations, 0);
  EXPECT_GT(cells[0].elements, cells[0].patches);
  EXPECT_EQ(cells[1].elements, cells[1].patches);
  while (!solver.done()) solver.round();
  cells = solver.cellFigures();
  EXPECT_GT(cells[1].elements, cells[1].patches);
}

// Bitwise the same on one thread and two, with uniform and adaptive elements.
TEST(CellElements, SameForOneAndTwoThreads) {
  const TwoRooms t = twoRoomsAtTheCell();
  for (Subdivide how : {Subdivide::Uniform, Subdivide::Adaptive}) {
    auto solve = [&](int threads) {
      CellSolver solver(t.scene, t.patches, twoRoomsPartition(t.patches), elementOptions(how, 0.05, threads),
                        {kCellM, 8, 4});
      while (!solver.done()) solver.round();
      return std::pair{solver.elements().elements.size(), solver.displayElementRadiosity()};
    };
    EXPECT_EQ(solve(1), solve(2)) << toString(how);
  }
}

}  // namespace
}  // namespace radmesh
