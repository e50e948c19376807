// Light crossing a portal in direction bins (CellSolveSettings::portalBins, docs/cells.md).
#include <gtest/gtest.h>

#include <cmath>

#include "solver/formfactors/direction_bins.h"
#include "solver/io/builtin_scenes.h"
#include "solver/io/scene_builder.h"
#include "solver/meshing/meshing.h"
#include "solver/radiosity/cell_solver.h"
#include "solver/scene/scene_error.h"
#include "tests/solver/radiosity/two_rooms_cells.h"

namespace radmesh {
namespace {

using test::reflectedInRoom;
using test::TwoRooms;
using test::twoRoomsPartition;

// A beam: everything black but room B's floor (rho 0.5), lit by a panel high on A's far wall
// (x = 0, y 1.8..2.2, z 2.2..2.6) facing the door. Its light goes down through the door onto B's
// floor along y = 2, and what the floor reflects meets only black surfaces: B's floor shows where
// the beam lands, once.
Scene beamScene() {
  SceneBuilder b("beam");
  const int black = b.addMaterial("black", Rgb(0.0));
  const int floor = b.addMaterial("floor", Rgb(0.5));
  const int panel = b.addMaterial("panel", Rgb(0.0), Rgb(100.0));
  b.addRoom({0, 0, 0}, {4, 4, 2.7}, {black, black, black},
            {{kXMax, {4, 1.55, 0}, {4, 2.45, 2.1}, 0.2, -1, -1, "door"},
             {kXMin, {0, 1.8, 2.2}, {0, 2.2, 2.6}, 0.0, -1, panel, "panel"}},
            "A");
  b.addRoom({4.2, 0, 0}, {8.2, 4, 2.7}, {floor, black, black},
            {{kXMin, {4.2, 1.55, 0}, {4.2, 2.45, 2.1}, 0.0, -1, -1, "door"}}, "B");
  return b.take();
}

SolveOptions hemicube(int threads = 1) {
  SolveOptions o;
  o.projection = Projection::Hemicube;
  o.resolution = 64;
  o.until = 1.0;
  o.untilUnshot = 0.001;
  o.effects = EffectsMode::All;
  o.threads = threads;
  return o;
}

// The power B's floor patches wholly within x0..x1, y0..y1 reflect (radiosity times area, over RGB).
double floorPower(const std::vector<Patch>& patches, const std::vector<Rgb>& b, double x0, double x1, double y0,
                  double y1) {
  double sum = 0.0;
  for (size_t j = 0; j < patches.size(); ++j) {
    const Patch& p = patches[j];
    bool inside = p.normal.z > 0.5 && std::abs(p.centroid.z) < 1e-9;
    for (int k = 0; k < p.vertexCount; ++k) {
      const Vec3& v = p.vertices[k];
      inside = inside && v.x >= x0 - 1e-9 && v.x <= x1 + 1e-9 && v.y >= y0 - 1e-9 && v.y <= y1 + 1e-9;
    }
    if (inside) sum += (b[j].r + b[j].g + b[j].b) * p.areaM2;
  }
  return sum;
}

std::vector<Rgb> solveCells(const Scene& scene, const std::vector<Patch>& patches, const SolveOptions& o, int bins) {
  CellSolver cells(scene, patches, twoRoomsPartition(patches), o, {kDefaultCellM, 16, bins});
  while (!cells.done()) cells.round();
  return cells.radiosity();
}

// The beam lands on B's floor in a strip along the door (y 1.5..2.5) and, at the far wall, no
// wider than y 0.93..3.07 (the panel's edges past the jambs: 1.8 - 0.65 * 8.2 / 4.2 and mirrored).
// The whole-building solve lights the strip and leaves the floor beyond y 0.77 and 3.42 (whole
// patches of the 0.381 m grid) dark; re-emitted diffusely from the doorway, the light lands there
// too and the strip gets a third of its light; kept in 8 x 8 bins, it goes on where the beam goes.
// Figures measured at hemicube 64 (docs/cells.md): strip +2 % with bins, -68 % diffuse; the dark
// floor 0 with bins, 30 % of the strip's light diffuse.
TEST(PortalBins, TheBeamGoesOnThroughTheDoor) {
  const Scene scene = beamScene();
  const std::vector<Patch> patches = meshScene(scene);
  auto strip = [&](const std::vector<Rgb>& b) { return floorPower(patches, b, 4.2, 8.2, 1.5, 2.5); };
  auto dark = [&](const std::vector<Rgb>& b) {
    return floorPower(patches, b, 4.2, 8.2, 0.0, 0.77) + floorPower(patches, b, 4.2, 8.2, 3.42, 4.0);
  };
  ProgressiveSolver whole(scene, patches, hemicube());
  while (!whole.done()) whole.step();
  ASSERT_GT(strip(whole.radiosity()), 0.0);
  EXPECT_EQ(dark(whole.radiosity()), 0.0);

  const std::vector<Rgb> binned = solveCells(scene, patches, hemicube(), 8);
  EXPECT_NEAR(strip(binned) / strip(whole.radiosity()), 1.0, 0.1);
  EXPECT_EQ(dark(binned), 0.0);
  const std::vector<Rgb> diffuse = solveCells(scene, patches, hemicube(), 0);
  EXPECT_LT(strip(diffuse) / strip(whole.radiosity()), 0.4);
  EXPECT_GT(dark(diffuse) / strip(diffuse), 0.2);
}

SolveOptions twoRoomsOptions(double untilUnshot, int threads = 1) {
  SolveOptions o = hemicube(threads);
  o.resolution = 32;
  o.untilUnshot = untilUnshot;
  return o;
}

// Every round the building's ledger and each cell's balance; two threads give the same bits.
TEST(PortalBins, LedgerBalancesAndTheSameBitsOnOneAndTwoThreads) {
  const TwoRooms t;
  auto solve = [&](int threads) {
    CellSolver cells(t.scene, t.patches, twoRoomsPartition(t.patches), twoRoomsOptions(0.02, threads), {kDefaultCellM, 8, 4});
    while (!cells.done()) {
      cells.round();
      EXPECT_LE(cells.ledger().imbalance(), 1e-9);
      double out = 0.0, in = 0.0;
      for (const CellFigures& cell : cells.cellFigures()) {
        EXPECT_LE(cell.ledger.imbalance(), 1e-9) << cell.name;
        out += cell.ledger.portalOut, in += cell.ledger.portalIn;
      }
      EXPECT_NEAR(out, in, 1e-12 * cells.ledger().emitted);
    }
    EXPECT_LE(cells.ledger().unshotFraction(), 0.02);
    EXPECT_GT(cells.cellFigures()[1].ledger.portalIn, 0.0);
    return cells.radiosity();
  };
  EXPECT_EQ(solve(1), solve(2));
}

// Room B, lit only through the door, against the whole-building solve (both to 1 % unshot, same
// mesh and hemicube 32): re-emitted diffusely its reflected light is +27 % off
// (CellSolver.ReflectedLightPerRoomNearTheWholeBuildingSolve); measured with 4 x 4 bins +7.6 %,
// with 8 x 8 +6.2 %.
TEST(PortalBins, RoomBNearTheWholeBuildingSolve) {
  const TwoRooms t;
  const SolveOptions o = twoRoomsOptions(0.01);
  ProgressiveSolver whole(t.scene, t.patches, o);
  while (!whole.done()) whole.step();
  const double error =
      reflectedInRoom(t.scene, t.patches, solveCells(t.scene, t.patches, o, 8), false) / reflectedInRoom(t.scene, t.patches, whole.radiosity(), false) - 1.0;
  EXPECT_GT(error, 0.0);
  EXPECT_LT(error, 0.09);
}

// One bin is every direction: the diffuse portal of portalBins 0, bit for bit.
TEST(PortalBins, OneBinIsTheDiffusePortal) {
  const TwoRooms t;
  const SolveOptions o = twoRoomsOptions(0.05);
  EXPECT_EQ(solveCells(t.scene, t.patches, o, 1), solveCells(t.scene, t.patches, o, 0));
}

TEST(PortalBins, RefusesWhatItCannotSolve) {
  const TwoRooms t;
  const Scene& scene = t.scene;
  const std::vector<Patch>& patches = t.patches;
  EXPECT_THROW(CellSolver(scene, patches, twoRoomsPartition(patches), hemicube(), {kDefaultCellM, 16, -1}), OptionError);
  EXPECT_THROW(CellSolver(scene, patches, twoRoomsPartition(patches), hemicube(), {kDefaultCellM, 16, kMaxPortalBins + 1}),
               OptionError);
  SolveOptions mesh;
  mesh.backend = Backend::Mesh;
  mesh.projection = Projection::Plane;
  mesh.resolution = 16;
  mesh.until = 1.0;
  mesh.untilUnshot = 0.01;
  try {
    CellSolver(scene, patches, twoRoomsPartition(patches), mesh, {kDefaultCellM, 16, 4});
    ADD_FAILURE() << "the mesh back end cannot split rows by direction";
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("--backend native"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace radmesh
