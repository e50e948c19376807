#include "solver/radiosity/progressive_solver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <functional>
#include <limits>

#include "solver/backends/native/native_backend.h"
#include "solver/io/builtin_scenes.h"
#include "solver/meshing/meshing.h"
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
  // The near receivers' difference from their area-to-area values goes to the receivers beyond
  // them, which in a closed box is where it belongs: measured 0.0074 at 10 divisions, 0.0094 when
  // it was shared over the whole row, the near receivers too.
  EXPECT_LT(previous, 0.0085);
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

// Solves to the end and checks it stopped at the first iteration that left at most `fraction` of
// the emitted power unshot.
void expectStoppedFirstBelow(ProgressiveSolver& solver, double fraction) {
  ASSERT_TRUE(solveChecked(solver));
  const auto& h = solver.history();
  ASSERT_GE(h.size(), 2u);
  EXPECT_LE(h.back().ledger.unshotFraction(), fraction);
  EXPECT_GT(h[h.size() - 2].ledger.unshotFraction(), fraction);
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
  expectStoppedFirstBelow(byUnshot, 0.02);
  EXPECT_GT(byUnshot.history().size(), byC.history().size());
}

// With --until 1 and no unshot stop, C reaches 1 only by rounding: the solve stops instead once
// what is left is below what the ledger vouches for, at the first iteration that leaves that little.
TEST(ProgressiveSolver, WithoutAnUnshotStopItEndsWhenNothingMeasurableIsLeft) {
  const TestScene t = room();
  SolveOptions o = optionsFor(Projection::Plane, 16);
  o.until = 1.0;
  o.untilUnshot = 0.0;
  ProgressiveSolver solver(t.scene, t.patches, o);
  expectStoppedFirstBelow(solver, kLedgerTolerance);
  EXPECT_FALSE(solver.exhausted());  // it stopped on the rule, not for want of power
  EXPECT_LT(solver.convergence(), 1.0);
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

// The solve command drops the cache before the bake: the rows are gone, and shots after it project
// them again, to the same bits.
TEST(ProgressiveSolver, ADroppedFormFactorCacheIsEmptiedAndChangesNothing) {
  const TestScene t = room();
  SolveOptions o = test::fixedIterations(optionsFor(Projection::Plane, 64), 400);
  o.formFactorCacheBytes = size_t{64} << 20;
  ProgressiveSolver straight(t.scene, t.patches, o), dropped(t.scene, t.patches, o);
  solveChecked(straight);
  for (int i = 0; i < 300; ++i) dropped.step();
  ASSERT_GT(dropped.progress().cachedRows.size(), 100u);
  dropped.dropFormFactorCache();
  EXPECT_TRUE(dropped.progress().cachedRows.empty());
  solveChecked(dropped);
  EXPECT_TRUE(sameBits(straight.radiosity(), dropped.radiosity()));
  int hitsAfter[2] = {0, 0};
  for (int i = 300; i < 400; ++i) {
    hitsAfter[0] += straight.history()[i].cacheHits;
    hitsAfter[1] += dropped.history()[i].cacheHits;
  }
  EXPECT_LT(hitsAfter[1], hitsAfter[0]);  // its rows were projected again
  EXPECT_EQ(dropped.options().formFactorCacheBytes, o.formFactorCacheBytes);
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

// A faulty back end: native rows, but from the given shot on every form factor is tripled, so the
// receivers get more light than the shooter sent.
class LightMakingBackend final : public FormFactorBackend {
 public:
  LightMakingBackend(const TestScene& t, const SolveOptions& o, int faultyShot)
      : patches_(t.patches), native_(t.scene, patches_, o), faultyShot_(faultyShot) {}
  void computeRows(std::span<const int> shooters, std::vector<FormFactorRow>& rows) override {
    native_.computeRows(shooters, rows);
    if (++shots_ < faultyShot_) return;
    for (FormFactorRow& row : rows)
      for (double& f : row.formFactors) f *= 3.0;
  }
  ProjectionSummary projectionSummary() const override { return native_.projectionSummary(); }
  ItemBuffer singlePlaneItemBuffer(int shooter) override { return native_.singlePlaneItemBuffer(shooter); }
  void receiversSplit(std::span<const int> origin) override { native_.receiversSplit(origin); }

 private:
  std::vector<Patch> patches_;
  NativeBackend native_;
  int faultyShot_;
  int shots_ = 0;
};

TEST(ProgressiveSolver, ImbalancedLedgerStopsTheSolveNamingIterationAndTerms) {
  const TestScene box = furnace(2);
  const SolveOptions o = optionsFor(Projection::Plane);
  ProgressiveSolver solver(box.scene, box.patches, o, std::make_unique<LightMakingBackend>(box, o, 3));
  solver.step();
  solver.step();
  ASSERT_EQ(solver.history().size(), 2u);
  try {
    solver.step();
    FAIL() << "a row that creates light went through";
  } catch (const SolveError& e) {
    const std::string message = e.what();
    const Ledger& l = solver.ledger();  // as the faulty iteration left it
    EXPECT_GT(l.imbalance(), 1e-3);
    EXPECT_NE(message.find("iteration 3:"), std::string::npos) << message;
    for (const auto& [term, value] : {std::pair{"emitted", l.emitted}, {"absorbed", l.absorbed}, {"unshot", l.unshot},
                                      {"not captured", l.notCaptured}, {"escaped", l.escaped}})
      EXPECT_NE(message.find(fmt::format("{} {:.17g} W", term, value)), std::string::npos) << term << ": " << message;
  }
  EXPECT_EQ(solver.history().size(), 2u);  // the iteration that did not balance is not recorded
}

TEST(ProgressiveSolver, BalancedLedgerPassesTheCheckEveryIteration) {
  const TestScene box = furnace(2);
  const SolveOptions o = optionsFor(Projection::Plane);
  ProgressiveSolver solver(box.scene, box.patches, o, std::make_unique<LightMakingBackend>(box, o, 1000000));
  for (int i = 0; i < 10; ++i) EXPECT_LE(solver.step().ledger.imbalance(), 1e-9);
}

// two-rooms is closed, yet at hemicube 32 on a 0.75 m mesh some pixel centres lie on seams where
// patch edges meet in T-junctions (the door passage) and fall outside both sides by rounding: that
// light hits nothing. It is booked as escaped, so the ledger balances to the end (it stopped at
// iteration 189 when a closed scene booked no escape).
TEST(ProgressiveSolver, LightThroughSeamsOfAClosedSceneIsBookedAsEscaped) {
  const Scene scene = builtinScene("two-rooms");
  SolveOptions o = optionsFor(Projection::Hemicube, 32);
  o.until = 1.0;
  o.untilUnshot = 0.01;
  o.effects = EffectsMode::Auto;  // escape off, as radmesh solve plans it
  ProgressiveSolver solver(scene, meshScene(scene, 0.75), o);
  EXPECT_FALSE(solver.effectsPlan().escape);
  ASSERT_TRUE(solveChecked(solver));
  const Ledger& l = solver.ledger();
  EXPECT_GT(l.escaped, 0.0);
  EXPECT_LT(l.escaped, 1e-3 * l.emitted);  // rounding-level seams, not openings
  EXPECT_EQ(l.lightOutside, 0.0);
  EXPECT_LE(l.unshotFraction(), 0.01);
}

// The message for bad input to the solver: the element and the value, as the loaders give them.
std::string refusal(const TestScene& t) {
  try {
    ProgressiveSolver solver(t.scene, t.patches, optionsFor(Projection::Plane));
  } catch (const SceneError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(ProgressiveSolver, RefusesNonFiniteOrOutOfRangeInputNamingElementAndValue) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    const char* what;
    std::function<void(TestScene&)> spoil;
    std::vector<std::string> named;
  };
  const std::vector<Case> cases = {
      {"NaN polygon vertex", [&](TestScene& t) { t.scene.polygons[1].vertices[2].y = nan; }, {"polygon 1", "vertex (1, nan, 0.9)"}},
      {"infinite patch vertex", [&](TestScene& t) { t.patches[5].vertices[0].x = inf; }, {"patch 5", "vertex (inf"}},
      {"NaN centroid", [&](TestScene& t) { t.patches[2].centroid.z = nan; }, {"patch 2", "centroid", "nan)"}},
      {"infinite emittance", [&](TestScene& t) { t.scene.materials[0].emittance.g = inf; },
       {"material 'grey'", "emittance inf"}},
      {"NaN emittance", [&](TestScene& t) { t.scene.materials[0].emittance.b = nan; }, {"material 'grey'", "emittance nan"}},
      {"negative emittance", [&](TestScene& t) { t.scene.materials[0].emittance.r = -1.0; }, {"emittance -1"}},
      {"negative area", [&](TestScene& t) { t.patches[4].areaM2 = -0.25; }, {"patch 4", "area -0.25"}},
      {"zero area", [&](TestScene& t) { t.patches[3].areaM2 = 0.0; }, {"patch 3", "area 0 "}},
      {"NaN area", [&](TestScene& t) { t.patches[7].areaM2 = nan; }, {"patch 7", "area nan"}},
      {"rho above 1", [&](TestScene& t) { t.scene.materials[0].rho.g = 1.5; }, {"material 'grey'", "reflectance 1.5"}},
      {"negative rho", [&](TestScene& t) { t.scene.materials[0].rho.r = -0.1; }, {"reflectance -0.1"}},
      {"NaN rho", [&](TestScene& t) { t.scene.materials[0].rho.b = nan; }, {"reflectance nan"}},
      {"unknown material", [&](TestScene& t) { t.patches[6].material = 9; }, {"patch 6", "material 9"}},
  };
  for (const Case& c : cases) {
    TestScene t = furnace(2);
    c.spoil(t);
    const std::string message = refusal(t);
    for (const std::string& name : c.named) EXPECT_NE(message.find(name), std::string::npos) << c.what << ": " << message;
  }
  // A reflectance of exactly 1 (a perfect mirror of diffuse light) is solvable.
  TestScene white = furnace(2);
  white.scene.materials[0].rho = Rgb(1.0);
  EXPECT_EQ(refusal(white), "accepted");
}

TEST(ProgressiveSolver, NaNUnshotPowerIsAnErrorNotAPatchPassedOver) {
  const TestScene box = furnace(2);
  NativeBackend native(box.scene, box.patches, optionsFor(Projection::Plane));
  const std::vector<int> rank = {0, 1, 2, 3};
  const std::vector<double> power = {1.0, std::numeric_limits<double>::quiet_NaN(), 3.0, 0.0};
  try {
    native.selectShooters(power, rank, 2);
    FAIL() << "a NaN unshot power was passed over";
  } catch (const SolveError& e) {
    EXPECT_NE(std::string(e.what()).find("patch 1 has a NaN unshot power"), std::string::npos) << e.what();
  }
  EXPECT_EQ(native.selectShooters(std::vector<double>{1.0, 2.0, 3.0, 0.0}, rank, 2), (std::vector<int>{2, 1}));
}

}  // namespace
}  // namespace radmesh
