// Adaptive subdivision (--subdivide adaptive): exact, thread-independent splits, a balanced ledger,
// refinement along shadow edges, and the exact shadow test: a square light over a floor with a
// square occluder between them, against the closed-form direct light.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "solver/backends/mesh/mesh_backend.h"
#include "solver/formfactors/analytic_form_factor.h"
#include "solver/formfactors/near_field.h"
#include "solver/io/builtin_scenes.h"
#include "solver/meshing/elements.h"
#include "solver/meshing/meshing.h"
#include "solver/radiosity/adaptive_split.h"
#include "solver/scene/scene_error.h"
#include "tests/solver/solver_test_helpers.h"

namespace radmesh::test {
namespace {

// A 2 x 2 m floor (z = 0, rho 0.5, 4 x 4 patches) under a 0.3 m square light 1 m above it
// (3 x 3 patches facing down, 100 W/m^2), with a black 0.4 m square occluder at z = 0.5 between
// them (facing up), off the light's axis so its shadow edges cross the floor's patches. Nothing
// the floor reflects comes back to it (the light and occluder are black, the scene open), so
// after the light's shots the floor's B is exactly rho E F(point -> the part of the light it sees).
struct ShadowScene {
  static constexpr double kRho = 0.5, kEmittance = 100.0, kLightZ = 2.0, kOccluderZ = 0.4;
  static constexpr double kLight = 0.15;  // half-side, centred on the z axis
  static constexpr int kLightCuts = 6;    // the light is kLightCuts^2 patches
  static constexpr double kOccluderX = 0.2, kOccluderY = 0.1;  // its centre
  static constexpr double kOccluder = 0.25;                    // half-side
  TestScene t;
  ShadowScene() {
    t.scene.source = "exact shadow";
    t.scene.materials = {grey(kRho), grey(0.0, kEmittance), grey(0.0)};
    const Vec3 floor(-1, -1, 0), light(-kLight, -kLight, kLightZ);
    const Vec3 occluder(kOccluderX - kOccluder, kOccluderY - kOccluder, kOccluderZ);
    addPolygon(t.scene, floor, Vec3(2, 0, 0), Vec3(0, 2, 0), 0);
    addPolygon(t.scene, light, Vec3(0, 2 * kLight, 0), Vec3(2 * kLight, 0, 0), 1);  // facing down
    addPolygon(t.scene, occluder, Vec3(2 * kOccluder, 0, 0), Vec3(0, 2 * kOccluder, 0), 2);
    addGrid(t.patches, floor, Vec3(2, 0, 0), Vec3(0, 2, 0), 4, 4, 0, 0);
    addGrid(t.patches, light, Vec3(0, 2 * kLight, 0), Vec3(2 * kLight, 0, 0), kLightCuts, kLightCuts, 1, 1);
    addGrid(t.patches, occluder, Vec3(2 * kOccluder, 0, 0), Vec3(0, 2 * kOccluder, 0), 1, 1, 2, 2);
  }
  static double formFactor(const Vec3& p, double x0, double x1, double y0, double y1) {
    if (!(x0 < x1 && y0 < y1)) return 0.0;
    const std::array<Vec3, 4> corners{Vec3(x0, y0, kLightZ) - p, Vec3(x1, y0, kLightZ) - p, Vec3(x1, y1, kLightZ) - p,
                                      Vec3(x0, y1, kLightZ) - p};
    return pointToPolygonFormFactor(corners);
  }
  // The oracle: from floor point p the occluder covers, on the light's plane, the square its
  // corners project to (scaled by kLightZ / kOccluderZ about p); what p sees of the light is the
  // light less its overlap with that square, both axis-aligned.
  static double exact(const Vec3& p) {
    const double s = kLightZ / kOccluderZ;
    const double ox0 = p.x + s * (kOccluderX - kOccluder - p.x), ox1 = p.x + s * (kOccluderX + kOccluder - p.x);
    const double oy0 = p.y + s * (kOccluderY - kOccluder - p.y), oy1 = p.y + s * (kOccluderY + kOccluder - p.y);
    const double seen = formFactor(p, -kLight, kLight, -kLight, kLight) -
                        formFactor(p, std::max(-kLight, ox0), std::min(kLight, ox1), std::max(-kLight, oy0),
                                   std::min(kLight, oy1));
    return kRho * kEmittance * seen;
  }
};

// The direct light of the 9 light patches: each shoots once; the floor then has all it will get.
SolveOptions shadowOptions(int threads = 1) {
  return fixedIterations(optionsFor(Projection::Hemicube, 256, threads), ShadowScene::kLightCuts * ShadowScene::kLightCuts);
}

// RMS over a 200 x 200 grid of floor points of the solved B (of the element holding the point)
// less the exact, relative to the brightest exact value.
double floorRmsError(const ProgressiveSolver& solver) {
  constexpr int kSamples = 200;
  std::vector<double> b(kSamples * kSamples, -1.0);
  const auto sampleAt = [](int i) { return -1.0 + (i + 0.5) * 2.0 / kSamples; };
  for (size_t e = 0; e < solver.elements().size(); ++e) {
    const Patch& el = solver.elements()[e];
    if (el.material != 0) continue;
    double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;  // floor elements are axis-aligned squares
    for (int k = 0; k < 4; ++k) {
      x0 = std::min(x0, el.vertices[k].x), x1 = std::max(x1, el.vertices[k].x);
      y0 = std::min(y0, el.vertices[k].y), y1 = std::max(y1, el.vertices[k].y);
    }
    for (int j = 0; j < kSamples; ++j)
      for (int i = 0; i < kSamples; ++i)
        if (sampleAt(i) >= x0 && sampleAt(i) < x1 && sampleAt(j) >= y0 && sampleAt(j) < y1)
          b[j * kSamples + i] = solver.elementRadiosity()[e].r;
  }
  double sum = 0.0, brightest = 0.0;
  for (int j = 0; j < kSamples; ++j)
    for (int i = 0; i < kSamples; ++i) {
      const double exact = ShadowScene::exact(Vec3(sampleAt(i), sampleAt(j), 0.0));
      EXPECT_GE(b[j * kSamples + i], 0.0) << "floor point " << i << ", " << j << " is in no element";
      sum += std::pow(b[j * kSamples + i] - exact, 2.0);
      brightest = std::max(brightest, exact);
    }
  return std::sqrt(sum / (kSamples * kSamples)) / brightest;
}

struct Solved {
  size_t elements = 0;
  double rms = 0.0;
};

Solved solveShadow(const SolveOptions& o) {
  const ShadowScene s;
  ProgressiveSolver solver(s.t.scene, s.t.patches, o);
  solveChecked(solver);
  return {solver.elements().size(), floorRmsError(solver)};
}

TEST(ExactShadow, TheOracleIsTheUnoccludedLightOutsideTheShadow) {
  // Far from the occluder's shadow, the whole light; under the occluder's middle, none of it.
  const double whole = ShadowScene::formFactor(Vec3(-0.9, -0.9, 0), -0.15, 0.15, -0.15, 0.15);
  EXPECT_NEAR(ShadowScene::exact(Vec3(-0.9, -0.9, 0)), 50.0 * whole, 1e-12);
  EXPECT_NEAR(ShadowScene::exact(Vec3(0.25, 0.125, 0)), 0.0, 1e-12);
}

// The table in docs/accuracy.md: RMS error over the floor against the element count. Adaptive
// (the default --split-contrast 0.1) reaches the finest uniform mesh's error with under half its
// elements.
TEST(ExactShadow, AdaptiveReachesTheErrorWithFewerElementsThanUniform) {
  std::printf("| subdivide | --min-element (m) | elements | floor RMS error (of the brightest) |\n|---|---|---|---|\n");
  Solved finestUniform;
  for (double m : {0.25, 0.125, 0.0625, 0.03125}) {
    finestUniform = solveShadow(subdivided(shadowOptions(), Subdivide::Uniform, m));
    std::printf("| uniform | %g | %zu | %.4f |\n", m, finestUniform.elements, finestUniform.rms);
  }
  Solved finestAdaptive;
  for (const char* regather : {"last", "all"})
    for (double m : {0.125, 0.0625, 0.03125, 0.015625}) {
      SolveOptions o = subdivided(shadowOptions(), Subdivide::Adaptive, m);
      o.splitRegatherAll = std::string(regather) == "all";
      const Solved run = solveShadow(o);
      if (!o.splitRegatherAll) finestAdaptive = run;
      std::printf("| adaptive, --split-regather %s | %g | %zu | %.4f |\n", regather, m, run.elements, run.rms);
    }
  std::fflush(stdout);
  EXPECT_LE(finestAdaptive.rms, finestUniform.rms);
  EXPECT_LT(2 * finestAdaptive.elements, finestUniform.elements);
}

// A patch's B against the area mean of its elements' (the split elements' listing, elements.h).
void expectPatchesAreAreaMeans(const ProgressiveSolver& solver) {
  std::vector<double> weighted(solver.patches().size(), 0.0), area(solver.patches().size(), 0.0);
  std::vector<int> patchOf(solver.elements().size());
  for (size_t p = 0; p < solver.patches().size(); ++p)
    for (int e : solver.elementsOf({static_cast<int>(p)})) {
      weighted[p] += solver.elementRadiosity()[e].r * solver.elements()[e].areaM2;
      area[p] += solver.elements()[e].areaM2;
    }
  for (size_t p = 0; p < solver.patches().size(); ++p) {
    EXPECT_NEAR(area[p], solver.patches()[p].areaM2, 1e-12) << "patch " << p;
    EXPECT_NEAR(weighted[p] / area[p], solver.radiosity()[p].r, 1e-9 * (1.0 + solver.radiosity()[p].r)) << "patch " << p;
  }
}

TEST(Adaptive, SplitCountsAreExactAndTheSameOnAnyThreadCount) {
  const ShadowScene s;
  ProgressiveSolver one(s.t.scene, s.t.patches, subdivided(shadowOptions(1), Subdivide::Adaptive, 0.0625));
  ProgressiveSolver three(s.t.scene, s.t.patches, subdivided(shadowOptions(3), Subdivide::Adaptive, 0.0625));
  solveChecked(one);
  solveChecked(three);
  // Every split follows the first light patch's shot: the other 35 patches' shadow edges lie
  // within 0.04 m of its own, among elements already split to the least size.
  std::vector<int> splits;
  for (const IterationRecord& r : one.history()) splits.push_back(r.elementsSplit);
  std::vector<int> expected(36, 0);
  expected[0] = 139;
  EXPECT_EQ(splits, expected);
  EXPECT_EQ(one.elements().size(), 53u + 3u * 139u);  // 53 patches; each split adds three elements
  ASSERT_EQ(three.elements().size(), one.elements().size());
  for (size_t e = 0; e < one.elements().size(); ++e) {
    EXPECT_EQ(three.elements()[e].vertices, one.elements()[e].vertices) << "element " << e;
    EXPECT_EQ(three.elementRadiosity()[e], one.elementRadiosity()[e]) << "element " << e;
  }
  EXPECT_EQ(three.radiosity(), one.radiosity());
}

TEST(Adaptive, LedgerBalancesAndPatchesAreAreaMeansOfTheirSplitElements) {
  for (Projection projection : {Projection::Plane, Projection::Hemicube}) {
    SCOPED_TRACE(toString(projection));
    // A closed box lit by its ceiling: light goes round, and elements split on every face.
    const TestScene t = closedBox(Vec3(1.0), 2, {grey(0.6), grey(0.3, 10.0)}, {0, 1, 0, 0, 0, 0});
    SolveOptions o = subdivided(fixedIterations(optionsFor(projection), 60), Subdivide::Adaptive, 0.06);
    o.splitContrast = 0.2;
    ProgressiveSolver solver(t.scene, t.patches, o);
    solveChecked(solver);
    EXPECT_GT(solver.elements().size(), t.patches.size());
    EXPECT_LE(solver.ledger().imbalance(), 1e-9);
    expectPatchesAreAreaMeans(solver);
  }
  const ShadowScene s;
  ProgressiveSolver shadow(s.t.scene, s.t.patches, subdivided(shadowOptions(), Subdivide::Adaptive, 0.0625));
  solveChecked(shadow);
  EXPECT_LE(shadow.ledger().imbalance(), 1e-9);
  expectPatchesAreAreaMeans(shadow);
}

TEST(Adaptive, RefinesAlongTheShadowEdge) {
  const ShadowScene s;
  SolveOptions o = subdivided(shadowOptions(), Subdivide::Adaptive, 0.03125);
  o.splitContrast = 100.0;  // the shadow criterion alone
  ProgressiveSolver solver(s.t.scene, s.t.patches, o);
  solveChecked(solver);
  // The edge of the occluder's shadow from the light's centre: a square, the occluder scaled by
  // kLightZ / (kLightZ - kOccluderZ) about the light's axis. Elements within 0.1 m of it against
  // those farther than 0.4 m.
  constexpr double kScale = ShadowScene::kLightZ / (ShadowScene::kLightZ - ShadowScene::kOccluderZ);
  const auto toEdge = [&](const Vec3& p) {
    const double half = kScale * ShadowScene::kOccluder;
    const double dx = std::abs(p.x - kScale * ShadowScene::kOccluderX) - half;
    const double dy = std::abs(p.y - kScale * ShadowScene::kOccluderY) - half;
    return dx > 0.0 || dy > 0.0 ? std::hypot(std::max(dx, 0.0), std::max(dy, 0.0)) : -std::max(dx, dy);
  };
  double nearArea = 0.0, farArea = 0.0;
  int nearCount = 0, farCount = 0;
  for (const Patch& e : solver.elements()) {
    if (e.material != 0) continue;
    const double d = toEdge(e.centroid);
    if (d < 0.1) nearArea += e.areaM2, ++nearCount;
    if (d > 0.4) farArea += e.areaM2, ++farCount;
  }
  ASSERT_GT(nearCount, 0);
  ASSERT_GT(farCount, 0);
  EXPECT_LT(nearArea / nearCount, 0.1 * farArea / farCount);  // the mean element 10x smaller at the edge
  EXPECT_GT(farArea / farCount, 0.2);  // far from it, the floor's 0.25 m^2 patches mostly stay whole
  o.splitShadows = false;  // and with neither criterion, nothing splits
  ProgressiveSolver none(s.t.scene, s.t.patches, o);
  solveChecked(none);
  EXPECT_EQ(none.elements().size(), s.t.patches.size());
}

// The mesh back end splits as the native one does: the same rows from the same item buffers on
// the paper's single plane, so the same elements and the same floor error; its ledger exact; and
// bitwise the same elements, light and machine counts on 1 and 3 threads.
TEST(MeshAdaptive, SplitsAsTheNativeBackEndDoesOnAnyThreadCount) {
  const auto options = [](Backend backend, int threads) {
    SolveOptions o = fixedIterations(optionsFor(Projection::Plane, 128, threads), ShadowScene::kLightCuts * ShadowScene::kLightCuts);
    o.backend = backend;
    o.machine = {16, 16, 16};
    return subdivided(o, Subdivide::Adaptive, 0.0625);
  };
  const ShadowScene s;
  SolveOptions rasterised = options(Backend::Native, 1);
  rasterised.elementRows = ElementRows::Rasterise;  // the mesh back end's way
  ProgressiveSolver native(s.t.scene, s.t.patches, rasterised);
  ProgressiveSolver one(s.t.scene, s.t.patches, options(Backend::Mesh, 1));
  ProgressiveSolver three(s.t.scene, s.t.patches, options(Backend::Mesh, 3));
  for (ProgressiveSolver* solver : {&native, &one, &three}) solveChecked(*solver);
  ASSERT_GT(native.elements().size(), s.t.patches.size());
  EXPECT_EQ(one.elements().size(), native.elements().size());
  const double nativeRms = floorRmsError(native), meshRms = floorRmsError(one);
  EXPECT_NEAR(meshRms, nativeRms, 1e-9);
  std::printf("| adaptive, plane 128², native | 0.0625 | %zu | %.4f |\n| adaptive, plane 128², mesh | 0.0625 | %zu | %.4f |\n",
              native.elements().size(), nativeRms, one.elements().size(), meshRms);
  std::fflush(stdout);
  EXPECT_LE(one.ledger().imbalance(), 1e-9);
  expectPatchesAreAreaMeans(one);
  ASSERT_EQ(three.elements().size(), one.elements().size());
  for (size_t e = 0; e < one.elements().size(); ++e) {
    EXPECT_EQ(three.elements()[e].vertices, one.elements()[e].vertices) << "element " << e;
    EXPECT_EQ(three.elementRadiosity()[e], one.elementRadiosity()[e]) << "element " << e;
  }
  const auto counts = [](ProgressiveSolver& solver) {
    return dynamic_cast<MeshBackend&>(solver.backend()).machine().costs().summary();  // host seconds left out
  };
  EXPECT_EQ(counts(three), counts(one));
}

// The gradient criterion on the mesh: each PE marks its elements from its neighbours' light, sent
// by the router, exactly as the host's markContrast does; one message per (element, neighbour)
// pair and one reduceMax (the brightest), charged to the phase "gradient test".
TEST(MeshAdaptive, TheGradientTestMarksOnThePesWhatTheHostMarks) {
  const ShadowScene s;
  const Elements elements = subdivideUniform(s.t.patches, 0.125);  // the floor 16 x 16
  const std::vector<std::vector<int>> neighbours = elementAdjacency(elements).neighbours;
  std::vector<double> reflected(elements.elements.size());
  for (size_t e = 0; e < reflected.size(); ++e) {  // a step across x = 0.3, a gentle slope elsewhere
    const Vec3& c = elements.elements[e].centroid;
    reflected[e] = (c.x > 0.3 ? 10.0 : 2.0) + 0.01 * c.y;
  }
  constexpr double kContrast = 0.1, kMinElement = 0.05;  // 0.125 m elements can split, the light's 0.05 m not
  std::vector<char> host(reflected.size(), 0), onPes(reflected.size(), 0);
  markContrast(elements, neighbours, reflected, kContrast, kMinElement, host);
  for (int threads : {1, 3}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    SolveOptions o = optionsFor(Projection::Plane, 32, threads);
    o.backend = Backend::Mesh;
    o.machine = {16, 16, 16};
    MeshBackend mesh(s.t.scene, s.t.patches, elements.elements, o);
    std::fill(onPes.begin(), onPes.end(), 0);
    EXPECT_TRUE(mesh.markContrast(neighbours, reflected, kContrast,
                                  [&](int e) { return splittable(elements.elements[e], kMinElement); }, onPes));
    EXPECT_EQ(onPes, host);
    const MeshPhaseCost& phase = mesh.lastShot().phases.back();
    ASSERT_EQ(phase.name, "gradient test");
    std::int64_t pairs = 0;
    for (const std::vector<int>& n : neighbours) pairs += static_cast<std::int64_t>(n.size());
    EXPECT_EQ(phase.counts.router.messages, pairs);
    EXPECT_EQ(phase.counts.reduce.ops, 1);
  }
  const auto marked = std::count(host.begin(), host.end(), 1);
  EXPECT_EQ(marked, 2 * 16 + 2 * 4);  // each side of the step: 16 of the floor's elements, 4 of the occluder's
}

// A split round updates the back end's receivers in place (receiversSplit) instead of making a
// new back end: its rows must be bitwise those of a back end made anew for the split elements.
TEST(Adaptive, ReceiversSplitComputesTheRowsOfANewBackend) {
  const ShadowScene s;
  for (Projection projection : {Projection::Plane, Projection::Hemicube, Projection::Analytic})
    for (int threads : {1, 3})
      for (ElementRows rows : {ElementRows::Rasterise, ElementRows::Share}) {
      SCOPED_TRACE(std::string(toString(projection)) + ", threads " + std::to_string(threads) + ", " + toString(rows));
      SolveOptions o = subdivided(optionsFor(projection, 128, threads), Subdivide::Adaptive, 0.01);
      o.elementRows = rows;
      Elements elements = patchesAsElements(s.t.patches);
      NativeBackend updated(s.t.scene, s.t.patches, elements, o);
      std::vector<FormFactorRow> before;
      updated.computeRows(range(16, 52), before);  // item buffers and scratch sized for the old elements
      for (int round = 0; round < 2; ++round) {  // every third element, then every second, splits
        std::vector<char> split(elements.elements.size(), 0);
        for (size_t e = 0; e < split.size(); e += 3 - round) split[e] = 1;
        updated.receiversSplit(splitElements(elements, split));
      }
      NativeBackend fresh(s.t.scene, s.t.patches, elements, o);
      std::vector<FormFactorRow> got, expected;
      updated.computeRows(range(16, 53), got);
      fresh.computeRows(range(16, 53), expected);
      ASSERT_EQ(got.size(), expected.size());
      for (size_t r = 0; r < got.size(); ++r) {
        EXPECT_EQ(got[r].receivers, expected[r].receivers) << "shooter " << got[r].shooter;
        EXPECT_EQ(got[r].formFactors, expected[r].formFactors) << "shooter " << got[r].shooter;
        EXPECT_EQ(got[r].backFaces, expected[r].backFaces) << "shooter " << got[r].shooter;
        EXPECT_EQ(got[r].capturedFraction, expected[r].capturedFraction) << "shooter " << got[r].shooter;
      }
      EXPECT_EQ(updated.singlePlaneItemBuffer(20).items, fresh.singlePlaneItemBuffer(20).items);
    }
}

// Neighbours across polygons: elements of two polygons sharing part of an edge, coplanar or at a
// concave fold; not at a convex fold, nor back to back.
TEST(Adaptive, NeighboursCrossPolygonSeamsWhereLightPasses) {
  // A closed box cut 2 x 2 a face (normals inward: every fold concave): each patch touches its
  // face's three others and shares an edge with one patch of each of the two faces it borders.
  const TestScene box = closedBox(Vec3(1.0), 2, {grey(0.5)});
  const std::vector<std::vector<int>> n = elementAdjacency(patchesAsElements(box.patches)).neighbours;
  for (size_t e = 0; e < n.size(); ++e) {
    EXPECT_EQ(n[e].size(), 5u) << "patch " << e;
    EXPECT_EQ(std::count_if(n[e].begin(), n[e].end(), [&](int o) { return box.patches[o].polygon != box.patches[e].polygon; }), 2)
        << "patch " << e;
  }
  EXPECT_EQ(n[0], (std::vector<int>{1, 2, 3, 8, 16}));  // the floor's corner at the origin
  // Coplanar: a 1 m patch of polygon 0 beside two 0.5 m patches of polygon 1, whose edges lie on
  // its own (a T-junction), and a third of polygon 2 touching it at a corner only.
  std::vector<Patch> flat{makePatch({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}, 0, 0),
                          makePatch({Vec3(1, 0, 0), Vec3(1.5, 0, 0), Vec3(1.5, 0.5, 0), Vec3(1, 0.5, 0)}, 0, 1),
                          makePatch({Vec3(1, 0.5, 0), Vec3(1.5, 0.5, 0), Vec3(1.5, 1, 0), Vec3(1, 1, 0)}, 0, 1),
                          makePatch({Vec3(1, 1, 0), Vec3(1.5, 1, 0), Vec3(1.5, 1.5, 0), Vec3(1, 1.5, 0)}, 0, 2)};
  const std::vector<std::vector<int>> coplanar = elementAdjacency(patchesAsElements(flat)).neighbours;
  EXPECT_EQ(coplanar[0], (std::vector<int>{1, 2}));
  EXPECT_EQ(coplanar[3], (std::vector<int>{2}));  // polygon 2 borders polygon 1's patch 2 along y = 1
  // A convex fold (a ridge: each face behind the other) and a face back to back with the first:
  // no neighbours.
  const std::vector<Patch> ridge{makePatch({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 1), Vec3(0, 1, 1)}, 0, 0),
                                 makePatch({Vec3(0, 1, 1), Vec3(1, 1, 1), Vec3(1, 2, 0), Vec3(0, 2, 0)}, 0, 1),
                                 makePatch({Vec3(0, 0, 0), Vec3(0, 1, 1), Vec3(1, 1, 1), Vec3(1, 0, 0)}, 0, 2)};
  const ElementAdjacency ridged = elementAdjacency(patchesAsElements(ridge));
  for (const std::vector<int>& none : ridged.neighbours) EXPECT_TRUE(none.empty());
}

// A step in the light along a seam between two polygons splits the elements on both sides: a floor
// of two 1 x 1 m polygons (rho 0.8 and 0.2, 2 x 2 patches of 0.5 m each) under a 1 m^2 light 10 m
// up, whose light varies by under 4 % over the floor: only the seam's step splits.
TEST(Adaptive, AStepAcrossAPolygonSeamSplits) {
  TestScene t;
  t.scene.source = "seam";
  t.scene.materials = {grey(0.8), grey(0.2), grey(0.0, 100.0)};
  const Vec3 left(-1, -0.5, 0), right(0, -0.5, 0), light(-0.5, -0.5, 10);
  addPolygon(t.scene, left, Vec3(1, 0, 0), Vec3(0, 1, 0), 0);
  addPolygon(t.scene, right, Vec3(1, 0, 0), Vec3(0, 1, 0), 1);
  addPolygon(t.scene, light, Vec3(0, 1, 0), Vec3(1, 0, 0), 2);  // facing down
  addGrid(t.patches, left, Vec3(1, 0, 0), Vec3(0, 1, 0), 2, 2, 0, 0);
  addGrid(t.patches, right, Vec3(1, 0, 0), Vec3(0, 1, 0), 2, 2, 1, 1);
  addGrid(t.patches, light, Vec3(0, 1, 0), Vec3(1, 0, 0), 1, 1, 2, 2);
  ProgressiveSolver solver(t.scene, t.patches, subdivided(fixedIterations(optionsFor(Projection::Analytic), 1),
                                                          Subdivide::Adaptive, 0.125));
  solveChecked(solver);
  // The four patches on the seam split (round 1), then the two children of each on the seam
  // (round 2), down to 0.125 m: 4 + 8 splits, three elements more each.
  EXPECT_EQ(solver.history().front().elementsSplit, 12);
  EXPECT_EQ(solver.elements().size(), t.patches.size() + 3u * 12u);
  for (const Patch& e : solver.elements())  // the 0.125 m elements are those within 0.25 m of the seam
    if (e.material != 2) {
      const double toSeam = std::min(std::abs(e.vertices[0].x), std::abs(e.vertices[2].x));  // opposite corners
      EXPECT_EQ(longestEdge(e) < 0.2, toSeam < 0.2) << "element at " << e.centroid.x << ", " << e.centroid.y;
    }
}

// Splitting wherever the light changes at all, adaptive subdivision stays within the count the
// up-front refusal bounds it by (elementCuts squared a patch), and no element is shorter than the
// minimum: the bound that lets the solve split without a cap at run time.
TEST(Adaptive, SplittingEverywhereStaysWithinTheRefusalsBound) {
  const ShadowScene s;
  constexpr double kMin = 0.06;
  SolveOptions o = subdivided(shadowOptions(), Subdivide::Adaptive, kMin);
  o.splitContrast = 1e-9;
  ProgressiveSolver solver(s.t.scene, s.t.patches, o);
  while (!solver.done()) solver.step();
  const std::vector<Patch>& elements = solver.elements();
  // The floor's 0.5 m patches split at most three times (0.0625 m), into 64 elements each, and all
  // but a few (in the umbra, black all over) do.
  const auto floor = std::ranges::count_if(elements, [](const Patch& e) { return e.material == 0; });
  EXPECT_LE(floor, 16 * 64);
  EXPECT_GT(floor, 16 * 60);
  EXPECT_LE(static_cast<double>(elements.size()), countElements(s.t.patches, kMin));
  // Not the light's elements: its 0.05 m patches were smaller to begin with.
  for (const Patch& e : elements)
    if (e.material == 0) {
      EXPECT_GE(longestEdge(e), kMin);
    }
}

TEST(Adaptive, OptionsAreRefusedNamingTheFix) {
  const ShadowScene s;
  SolveOptions o = subdivided(shadowOptions(), Subdivide::Adaptive, 0.0);
  EXPECT_THROW(ProgressiveSolver(s.t.scene, s.t.patches, o), OptionError);
  o.minElementM = 0.1;
  o.splitContrast = 0.0;
  EXPECT_THROW(ProgressiveSolver(s.t.scene, s.t.patches, o), OptionError);
  // Splitting everywhere down to 1e-5 m could make 4.34e10 elements (the floor's and the occluder's
  // 0.5 m patches 17 x 50000^2, the light's 0.05 m ones 36 x 5000^2): refused up front, where it
  // refined shadow edges for hours before 2026-12-03.
  o.splitContrast = 0.1;
  o.minElementM = 1e-5;
  try {
    ProgressiveSolver solver(s.t.scene, s.t.patches, o);
    ADD_FAILURE() << "--min-element 1e-5 was taken";
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("--min-element 1e-05 m could let adaptive subdivision split the 53 patches into 4.34e+10 elements"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("use a larger --min-element"), std::string::npos) << e.what();
  }
}

// The shadow criterion's rays see through the hierarchy exactly what they see testing every patch:
// random rays between points of the office's patches, some blocked, some not, all agreeing.
// One element in `oneIn` marked to split, drawn by a linear congruential generator from `state`.
std::vector<char> randomSplits(size_t elements, unsigned& state, unsigned oneIn) {
  std::vector<char> split(elements, 0);
  for (char& s : split) {
    state = state * 1664525u + 1013904223u;
    s = (state >> 16) % oneIn == 0;
  }
  return split;
}

// The neighbours kept across split rounds are those found from scratch, bit for bit (a resumed
// solve finds them from scratch and must go on as the straight one): the office's 0.75 m patches
// split at random, a sixth of the elements a round, five rounds, with seams across polygons.
TEST(Adaptive, NeighboursKeptAcrossSplitsAreThoseFoundFromScratch) {
  Elements elements = patchesAsElements(meshScene(builtinScene("office"), 0.75));
  ElementAdjacency kept = elementAdjacency(elements);
  unsigned state = 777u;
  long crossPolygon = 0;
  for (int round = 0; round < 5; ++round) {
    const std::vector<char> split = randomSplits(elements.elements.size(), state, 6);
    const std::vector<int> origin = splitElements(elements, split);
    splitAdjacency(kept, elements, origin, split);
    const ElementAdjacency fresh = elementAdjacency(elements);
    ASSERT_EQ(kept.neighbours, fresh.neighbours) << "round " << round;
    ASSERT_EQ(kept.overlapping, fresh.overlapping) << "round " << round;
    for (size_t e = 0; e < elements.elements.size(); ++e) {
      ASSERT_EQ(kept.boxes[e].lo, fresh.boxes[e].lo);
      ASSERT_EQ(kept.boxes[e].hi, fresh.boxes[e].hi);
    }
  }
  for (size_t e = 0; e < elements.elements.size(); ++e)
    for (int n : kept.neighbours[e]) crossPolygon += elements.elements[n].polygon != elements.elements[e].polygon;
  EXPECT_GT(elements.elements.size(), 8000u);
  EXPECT_GT(crossPolygon, 1000);  // the seams are in the comparison
}

// The near-field finder is renumbered across splits, not built anew: each shooter's near elements
// are those a fresh finder finds, on every round.
TEST(Adaptive, NearReceiversKeptAcrossSplitsAreThoseFoundFromScratch) {
  const std::vector<Patch> patches = meshScene(builtinScene("office"), 0.75);
  Elements elements = patchesAsElements(patches);
  NearFieldFinder kept(patches, elements.elements);
  const int n = static_cast<int>(patches.size());
  for (int i = 0; i < n; ++i) kept.receiversNear(i);  // every size class's grid built before the splits
  unsigned state = 4242u;
  size_t nearPairs = 0;
  for (int round = 0; round < 4; ++round) {
    const std::vector<char> split = randomSplits(elements.elements.size(), state, 5);
    const std::vector<int> origin = splitElements(elements, split);
    kept.receiversSplit(origin, split);
    NearFieldFinder fresh(patches, elements.elements);
    for (int i = 0; i < n; ++i) {
      ASSERT_EQ(kept.receiversNear(i), fresh.receiversNear(i)) << "round " << round << ", shooter " << i;
      nearPairs += fresh.receiversNear(i).size();
    }
  }
  EXPECT_GT(nearPairs, 100000u);  // near receivers are in the comparison, not just empty lists
}

}  // namespace
}  // namespace radmesh::test
