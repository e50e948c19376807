#include "solver/radiosity/progressive_solver.h"

#include <gtest/gtest.h>

#include <cstring>

#include "solver/scene/scene_error.h"
#include "solver/projection/single_plane.h"
#include "tests/solver/solver_test_helpers.h"

namespace radmesh {
namespace {

using test::areaMean;
using test::optionsFor;
using test::solveChecked;
using test::TestScene;

// The furnace: a closed box, every wall emitting E and reflecting rho.
TestScene furnace(int divisions = 4) {
  return test::closedBox({1.0, 1.3, 0.9}, divisions, {test::grey(0.5, 1.0)});
}

// A room with an occluder: a box, a light in the ceiling, a floating table top (two-sided: two
// patches back to back) and walls of three reflectances.
TestScene room() {
  TestScene t = test::closedBox({3.0, 2.2, 2.5}, 6,
                                {test::grey(0.6), test::grey(0.3), {"red", Rgb(0.7, 0.2, 0.2), Rgb(0.0)},
                                 test::grey(0.0, 40.0, "light")},
                                {0, 0, 1, 0, 2, 0});
  t.scene.polygons.push_back({{{1.0, 0.8, 2.49}, {1.0, 1.2, 2.49}, {1.6, 1.2, 2.49}, {1.6, 0.8, 2.49}}, 3, "light"});
  test::addGrid(t.patches, {1.0, 0.8, 2.49}, {0, 0.4, 0}, {0.6, 0, 0}, 2, 2, 3, 6);
  t.scene.polygons.push_back({{{0.5, 0.5, 0.8}, {1.7, 0.5, 0.8}, {1.7, 1.4, 0.8}, {0.5, 1.4, 0.8}}, 0, "table"});
  test::addGrid(t.patches, {0.5, 0.5, 0.8}, {1.2, 0, 0}, {0, 0.9, 0}, 4, 3, 0, 7);   // top, facing up
  test::addGrid(t.patches, {0.5, 0.5, 0.79}, {0, 0.9, 0}, {1.2, 0, 0}, 4, 3, 0, 7);  // underside
  return t;
}

TEST(ProgressiveSolver, FurnaceConvergesToEOverOneMinusRho) {
  const TestScene box = furnace();
  for (Projection p : {Projection::Hemicube, Projection::Analytic}) {
    SolveOptions o = optionsFor(p, 128);
    o.until = 0.9999;
    ProgressiveSolver solver(box.scene, box.patches, o);
    ASSERT_TRUE(solveChecked(solver)) << toString(p);
    const double exact = 1.0 / (1.0 - 0.5);
    // The area mean is exact by energy conservation (nothing leaves a closed box)...
    EXPECT_NEAR(areaMean(box.patches, solver.displayRadiosity()), exact, 1e-9 * exact) << toString(p);
    EXPECT_NEAR(areaMean(box.patches, solver.radiosity()), exact, 1e-3 * exact) << toString(p);
    // ...and each patch is within what centroid-sampled form factors allow (see below).
    for (const Rgb& b : solver.radiosity()) EXPECT_NEAR(b.r, exact, 0.06 * exact) << toString(p);
    EXPECT_EQ(solver.ledger().notCaptured, 0.0);
    EXPECT_EQ(solver.ledger().escaped, 0.0);
  }
}

TEST(ProgressiveSolver, FurnaceErrorShrinksAsPatchesShrink) {
  // Centroid-sampled form factors are not reciprocal next to creases, where a patch's neighbour
  // is as near as the patch is large: there the error stays (the geometry is self-similar), but as
  // patches shrink, less of the area lies there.
  double previous = 1.0;
  for (int divisions : {3, 6, 10}) {
    const TestScene box = furnace(divisions);
    SolveOptions o = optionsFor(Projection::Analytic);
    o.until = 0.99999;
    o.formFactorCacheBytes = size_t{64} << 20;
    ProgressiveSolver solver(box.scene, box.patches, o);
    ASSERT_TRUE(solveChecked(solver));
    double squares = 0.0, area = 0.0, worst = 0.0;
    for (size_t j = 0; j < box.patches.size(); ++j) {
      const double error = solver.radiosity()[j].r - 2.0;
      squares += error * error * box.patches[j].areaM2;
      area += box.patches[j].areaM2;
      worst = std::max(worst, std::abs(error));
    }
    const double rms = std::sqrt(squares / area);
    EXPECT_LT(rms, previous) << divisions << " divisions; worst " << worst;
    EXPECT_LT(worst, 0.06 * 2.0) << divisions << " divisions";
    previous = rms;
  }
  EXPECT_LT(previous, 0.02 * 2.0);
}

TEST(ProgressiveSolver, LedgerBalancesAndThePlaneReportsItsMiss) {
  const TestScene t = room();
  for (Projection p : {Projection::Plane, Projection::Hemicube}) {
    const SolveOptions o = test::fixedIterations(optionsFor(p, 64), 150);
    ProgressiveSolver solver(t.scene, t.patches, o);
    solveChecked(solver);
    EXPECT_EQ(solver.history().size(), 150u);
    const Ledger& l = solver.ledger();
    EXPECT_NEAR(l.emitted, 40.0 * 0.24 * 3, 1e-9);  // 0.6 x 0.4 m at 40 W/m^2 in each of R, G, B
    double shot = 0.0;
    for (const IterationRecord& r : solver.history()) shot += r.shotPowerW;
    if (p == Projection::Plane) {
      EXPECT_NEAR(l.notCaptured, shot * (1.0 - singlePlaneCapturedFraction(3.0)), 1e-9 * shot);
      EXPECT_NEAR(solver.projectionSummary().capturedFraction, 0.91688, 1e-5);
      EXPECT_NEAR(solver.projectionSummary().deltaFormFactorSum, 0.91688, 1e-3);
    } else {
      EXPECT_EQ(l.notCaptured, 0.0);
    }
    EXPECT_EQ(l.escaped, 0.0);  // a closed room
    EXPECT_GT(l.absorbedByBackFaces, 0.0);  // the ceiling sees the light's unlit back
  }
}

TEST(ProgressiveSolver, ConvergenceFollowsThePaperAndStopsAtUntil) {
  const TestScene t = room();
  SolveOptions o = optionsFor(Projection::Plane, 64);
  o.until = 0.9;
  ProgressiveSolver solver(t.scene, t.patches, o);
  ASSERT_TRUE(solveChecked(solver));
  const auto& h = solver.history();
  const double s1 = h.front().shotPowerW;
  for (const IterationRecord& r : h) EXPECT_NEAR(r.convergence, 1.0 - r.shotPowerW / s1, 1e-12);
  EXPECT_GE(h.back().convergence, 0.9);
  EXPECT_LT(h[h.size() - 2].convergence, 0.9);
  EXPECT_EQ(h.front().shooters.size(), 1u);
  EXPECT_EQ(t.patches[h.front().shooters[0]].material, 3);  // a light shoots first
  EXPECT_GT(h.front().shotPowerW, h.back().shotPowerW);
}

// C follows the shooter's power only: in this room it passes 0.9 with much of the power unshot.
// --until-unshot stops on what is left instead, at the first iteration that leaves at most that.
TEST(ProgressiveSolver, UntilUnshotStopsOnThePowerLeftToShoot) {
  const TestScene t = room();
  SolveOptions o = optionsFor(Projection::Plane, 64);
  o.until = 0.9;
  ProgressiveSolver byC(t.scene, t.patches, o);
  ASSERT_TRUE(solveChecked(byC));
  EXPECT_GT(byC.ledger().unshot, 0.1 * byC.ledger().emitted);
  o.until = 1.0;
  o.untilUnshot = 0.02;
  ProgressiveSolver byUnshot(t.scene, t.patches, o);
  ASSERT_TRUE(solveChecked(byUnshot));
  const auto& h = byUnshot.history();
  ASSERT_GE(h.size(), 2u);
  EXPECT_LE(h.back().ledger.unshot, 0.02 * h.back().ledger.emitted);
  EXPECT_GT(h[h.size() - 2].ledger.unshot, 0.02 * h.back().ledger.emitted);
  EXPECT_GT(h.size(), byC.history().size());
}

bool sameBits(const std::vector<Rgb>& a, const std::vector<Rgb>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Rgb)) == 0;
}

TEST(ProgressiveSolver, ThreadCountDoesNotChangeABit) {
  const TestScene t = room();
  for (Projection p : {Projection::Plane, Projection::Hemicube}) {  // analytic refuses the room
    std::vector<Rgb> result[2];
    for (int threads : {1, 2}) {
      SolveOptions o = test::fixedIterations(optionsFor(p, 128, threads), 40);
      o.shooters = 2;
      ProgressiveSolver solver(t.scene, t.patches, o);
      solveChecked(solver);
      result[threads - 1] = solver.radiosity();
    }
    EXPECT_TRUE(sameBits(result[0], result[1])) << toString(p);
  }
  const TestScene box = furnace();
  std::vector<Rgb> result[2];
  for (int threads : {1, 2}) {
    const SolveOptions o = test::fixedIterations(optionsFor(Projection::Analytic, 64, threads), 40);
    ProgressiveSolver solver(box.scene, box.patches, o);
    solveChecked(solver);
    result[threads - 1] = solver.radiosity();
  }
  EXPECT_TRUE(sameBits(result[0], result[1])) << "analytic";
}

TEST(ProgressiveSolver, SeveralShootersPerIterationReachTheSameAnswer) {
  const TestScene box = furnace();
  std::vector<Rgb> b[2];
  for (int k : {1, 4}) {
    SolveOptions o = optionsFor(Projection::Analytic);
    o.shooters = k;
    o.until = 0.99999;
    ProgressiveSolver solver(box.scene, box.patches, o);
    ASSERT_TRUE(solveChecked(solver));
    EXPECT_EQ(solver.history().front().shooters.size(), static_cast<size_t>(k));
    b[k == 4] = solver.radiosity();
  }
  for (size_t j = 0; j < b[0].size(); ++j) EXPECT_NEAR(b[0][j].r, b[1][j].r, 1e-4);
}

TEST(ProgressiveSolver, FormFactorCacheServesReusedRowsAndChangesNothing) {
  const TestScene t = room();
  std::vector<Rgb> b[2];
  int reused = 0, hits = 0;
  for (size_t budget : {size_t{0}, size_t{64} << 20}) {
    SolveOptions o = test::fixedIterations(optionsFor(Projection::Plane, 64), 400);
    o.formFactorCacheBytes = budget;
    ProgressiveSolver solver(t.scene, t.patches, o);
    solveChecked(solver);
    b[budget > 0] = solver.radiosity();
    reused = solver.history().back().reusedRowsTotal;
    hits = 0;
    for (const IterationRecord& r : solver.history()) hits += r.cacheHits;
    if (budget == 0) {
      EXPECT_EQ(hits, 0);
    }
  }
  EXPECT_GT(reused, 10);
  EXPECT_EQ(hits, reused);  // with room for every row, every reused row is a hit
  EXPECT_TRUE(sameBits(b[0], b[1]));
}

TEST(ProgressiveSolver, ReuseComesLateAndAShortCacheMissesIt) {
  // Rows come back in nearly the order they were first shot (the paper's Table 1.3: reuse starts
  // once most patches have shot), so a least-recently-used cache shorter than that cycle never hits.
  const TestScene t = room();
  SolveOptions o = test::fixedIterations(optionsFor(Projection::Plane, 64), 400);
  o.formFactorCacheBytes = 64 * 1024;  // a few dozen rows of this room
  ProgressiveSolver solver(t.scene, t.patches, o);
  solveChecked(solver);
  int firstReuse = 0, hits = 0;
  for (const IterationRecord& r : solver.history()) {
    if (!firstReuse && r.reusedRows > 0) firstReuse = r.iteration;
    hits += r.cacheHits;
  }
  EXPECT_GT(firstReuse, static_cast<int>(t.patches.size()) / 2);
  EXPECT_EQ(hits, 0);
}

TEST(ProgressiveSolver, AmbientTermIsForDisplayOnly) {
  const TestScene box = furnace();
  SolveOptions o = test::fixedIterations(optionsFor(Projection::Hemicube, 64), 10);
  ProgressiveSolver solver(box.scene, box.patches, o);
  solveChecked(solver);
  const Ledger before = solver.ledger();
  // Early on, the ambient estimate already makes the mean right (Cohen et al. 1988): in a closed
  // box with one reflectance it is exact.
  EXPECT_NEAR(areaMean(box.patches, solver.displayRadiosity()), 2.0, 1e-9);
  EXPECT_LT(areaMean(box.patches, solver.radiosity()), 1.9);
  for (size_t j = 0; j < box.patches.size(); ++j) EXPECT_GE(solver.displayRadiosity()[j].r, solver.radiosity()[j].r);
  EXPECT_EQ(solver.ledger().absorbed, before.absorbed);

  o.ambient = false;
  ProgressiveSolver plain(box.scene, box.patches, o);
  solveChecked(plain);
  EXPECT_TRUE(sameBits(plain.displayRadiosity(), plain.radiosity()));
}

// An open box (the furnace without its lid) loses light through the top: the ambient estimate
// loses the same fraction, so the early picture is about as bright as the converged one will be,
// where Cohen's closed-room estimate is far too bright.
TEST(ProgressiveSolver, AmbientTermInAnOpenBoxLosesWhatEscapes) {
  TestScene box = furnace();
  std::vector<Patch> open;
  for (const Patch& p : box.patches)
    if (p.polygon != 1) open.push_back(p);  // polygon 1: the ceiling
  box.patches = open;
  SolveOptions o = test::fixedIterations(optionsFor(Projection::Hemicube, 64), 40);
  ProgressiveSolver early(box.scene, box.patches, o);
  solveChecked(early);
  o = test::fixedIterations(o, 3000);
  o.until = 0.99999;
  ProgressiveSolver converged(box.scene, box.patches, o);
  solveChecked(converged);
  const double truth = areaMean(box.patches, converged.radiosity());
  ASSERT_GT(early.ledger().escaped, 0.03 * early.ledger().emitted);
  // Half the patches have shot: the loss of those shots stands for the loss of the rest, to 5 %.
  const double shown = areaMean(box.patches, early.displayRadiosity());
  EXPECT_NEAR(shown, truth, 0.05 * truth);
  // The closed-room estimate: unshot power over the area, times 1 / (1 - rho), reflected with rho.
  double area = 0.0;
  for (const Patch& p : box.patches) area += p.areaM2;
  const double closedRoom = areaMean(box.patches, early.radiosity()) + 0.5 * (early.ledger().unshot / 3.0) / area / 0.5;
  EXPECT_GT(closedRoom, 1.1 * truth);
  EXPECT_LT(std::abs(shown - truth), std::abs(closedRoom - truth) / 3.0);
}

TEST(ProgressiveSolver, RefusesBadPatchesByName) {
  TestScene box = furnace(2);
  box.patches[3].areaM2 = 0.0;
  try {
    ProgressiveSolver solver(box.scene, box.patches, optionsFor(Projection::Plane));
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("patch 3"), std::string::npos) << e.what();
  }
  box = furnace(2);
  SolveOptions bad = optionsFor(Projection::Plane);
  bad.resolution = 4;
  EXPECT_THROW(ProgressiveSolver(box.scene, box.patches, bad), OptionError);
}

}  // namespace
}  // namespace radmesh
