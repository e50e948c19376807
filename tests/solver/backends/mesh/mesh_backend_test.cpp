// The mesh back end against the native one: the same item buffers pixel for pixel, the same form
// factors up to summation order, and load-balance depths that are counts of what arrived.
#include "solver/backends/mesh/mesh_backend.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <limits>
#include <numeric>
#include <random>

#include "emulator/memory_ledger.h"
#include "solver/backends/native/native_backend.h"
#include "solver/meshing/elements.h"
#include "solver/radiosity/progressive_solver.h"
#include "solver/scene/scene_error.h"
#include "tests/solver/backends/mesh/mesh_agreement.h"
#include "tests/solver/patch_fixtures.h"

namespace radmesh {
namespace {

using test::expectSameRow;
using test::sameItemBuffer;

using Meshed = test::MeshedScene;

const Meshed& builtin(const std::string& name) {
  static std::map<std::string, Meshed> cache;
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, test::meshedScene(name)).first;
  return it->second;
}

SolveOptions planeOptions(int resolution, int threads = 1) {
  SolveOptions o;
  o.backend = Backend::Mesh;
  o.projection = Projection::Plane;
  o.resolution = resolution;
  o.threads = threads;
  return o;
}

std::vector<int> someShooters(const Meshed& m, int count) { return test::someShooters(m.scene, m.patches, count); }

class MeshAgreement : public ::testing::TestWithParam<std::tuple<std::string, int, MappingKind>> {};

TEST_P(MeshAgreement, ItemBuffersAreTheNativeOnesAndRowsAgree) {
  const auto& [name, resolution, mapping] = GetParam();
  const Meshed& m = builtin(name);
  const SolveOptions o = planeOptions(resolution);
  NativeBackend native(m.scene, m.patches, o);
  MeshBackend mesh(m.scene, m.patches, o, {mapping});
  for (int shooter : someShooters(m, 2)) {
    EXPECT_TRUE(sameItemBuffer(mesh.singlePlaneItemBuffer(shooter), native.singlePlaneItemBuffer(shooter)))
        << name << " at " << resolution << ", " << toString(mapping) << ", shooter " << shooter;
    std::vector<FormFactorRow> meshRows, nativeRows;
    const int one[] = {shooter};
    mesh.computeRows(one, meshRows);
    native.computeRows(one, nativeRows);
    expectSameRow(meshRows[0], nativeRows[0], 1e-9);
  }
}

INSTANTIATE_TEST_SUITE_P(
    BuiltinScenes, MeshAgreement,
    ::testing::Combine(::testing::Values("office", "cornell", "two-rooms", "furnace"), ::testing::Values(64, 128),
                       ::testing::Values(MappingKind::Hierarchical, MappingKind::CutAndStack, MappingKind::Adaptive)),
    [](const auto& info) {
      std::string s = std::get<0>(info.param) + "_" + std::to_string(std::get<1>(info.param)) + "_" +
                      toString(std::get<2>(info.param));
      std::replace(s.begin(), s.end(), '-', '_');
      return s;
    });

TEST(MeshBackend, SeveralPlanesAtOnceGiveTheRowsOfOneAtATime) {
  const Meshed& m = builtin("cornell");
  const SolveOptions o = planeOptions(64);
  MeshBackend mesh(m.scene, m.patches, o);
  const std::vector<int> shooters = someShooters(m, 3);
  std::vector<FormFactorRow> together;
  mesh.computeRows(shooters, together);
  ASSERT_EQ(together.size(), 3u);
  for (int s = 0; s < 3; ++s) {
    std::vector<FormFactorRow> alone;
    mesh.computeRows(std::span<const int>(&shooters[s], 1), alone);
    expectSameRow(together[s], alone[0], 1e-12);
  }
}

// A shooter on the floor looking up at quads facing down (one partly off the plane, one wholly
// off it, one hiding part of another): their projections are rectangles the test computes itself.
struct Ceiling {
  Scene scene{"ceiling", {test::grey(0.5, 1.0)}, {}, {}};
  std::vector<Patch> patches;
  Ceiling() {
    patches.push_back(test::makePatch({{-0.05, -0.05, 0}, {0.05, -0.05, 0}, {0.05, 0.05, 0}, {-0.05, 0.05, 0}}));
    auto quad = [&](double x0, double x1, double y0, double y1, double z) {  // facing down
      patches.push_back(test::makePatch({{x0, y0, z}, {x0, y1, z}, {x1, y1, z}, {x1, y0, z}}));
    };
    quad(0.2, 0.5, 0.1, 0.3, 1.0);
    quad(-1.0, -0.4, -2.0, -1.0, 1.0);
    quad(0.25, 0.4, 0.0, 0.2, 0.8);   // in front of the first
    quad(2.5, 3.5, -0.5, 0.5, 1.0);   // partly beyond the plane's edge (a = 3)
    quad(3.7, 4.2, 0.0, 0.5, 1.0);    // wholly beyond it: never projected
    quad(-2.0, 2.0, 1.0, 2.5, 1.2);   // a tall strip
  }
};

TEST(MeshBackend, DepthsCountWhatArrivedAtEachPe) {
  const Ceiling c;
  const SolveOptions o = planeOptions(128);
  MeshBackend mesh(c.scene, c.patches, o);
  std::vector<FormFactorRow> rows;
  const int one[] = {0};
  mesh.computeRows(one, rows);
  const MeshShotStats& s = mesh.lastShot();
  // Recount: each quad's pixel bounding box (the pixels whose centres it may cover, widened by
  // one pixel and clipped to the plane: scan_conversion.cpp's rule) under the hierarchical mapping
  // of 128 pixels onto 64 PEs per axis (2 x 2 pixels a PE). Stage (a) puts a quad on the PE of its
  // upper-left pixel; stage (b) on every PE of that PE column down to its last pixel row.
  const int resolution = 128;
  const double pixelsPerUnit = resolution / (2.0 * o.ratio);
  auto pixelRange = [&](double low, double high) {
    const double begin = std::clamp(std::ceil(low - 0.5) - 1.0, 0.0, double(resolution));
    const double end = std::clamp(std::floor(high - 0.5) + 2.0, 0.0, double(resolution));
    return std::pair{int(begin), int(end)};
  };
  std::vector<int> depthA(4096, 0), depthB(4096, 0);
  int projected = 0;
  for (std::size_t j = 1; j < c.patches.size(); ++j) {
    glm::dvec2 low(1e300), high(-1e300);
    for (int k = 0; k < 4; ++k) {
      const Vec3 v = c.patches[j].vertices[k];  // the shooter's frame is the world's, at the origin
      const glm::dvec2 pixel = (glm::dvec2(v.x, v.y) / v.z + o.ratio) * pixelsPerUnit;
      for (double x : {pixel.x, pixel.y}) ASSERT_GT(std::abs(x - std::floor(x) - 0.5), 1e-6) << "on a centre line";
      low = glm::min(low, pixel);
      high = glm::max(high, pixel);
    }
    const auto [columnBegin, columnEnd] = pixelRange(low.x, high.x);
    const auto [rowBegin, rowEnd] = pixelRange(low.y, high.y);
    if (columnBegin >= columnEnd || rowBegin >= rowEnd) continue;
    ++projected;
    const int column = columnBegin / 2;
    ++depthA[rowBegin / 2 * 64 + column];
    for (int row = rowBegin / 2; row <= (rowEnd - 1) / 2; ++row) ++depthB[row * 64 + column];
  }
  ASSERT_EQ(projected, 5);
  EXPECT_EQ(s.depthA, depthA);
  EXPECT_EQ(s.depthB, depthB);
  EXPECT_EQ(s.depthAMax, *std::max_element(depthA.begin(), depthA.end()));
  EXPECT_EQ(s.depthBMax, *std::max_element(depthB.begin(), depthB.end()));
  EXPECT_EQ(s.depthBHist, depthHistogram(depthB));
  EXPECT_EQ(s.depthBHist[0], 4096 - std::count_if(depthB.begin(), depthB.end(), [](int d) { return d > 0; }));
  // The shot's cost is the sum of its phases.
  EXPECT_GT(s.emulatedSeconds, 0.0);
  double phaseSum = 0.0;
  for (const MeshPhaseCost& p : s.phases) phaseSum += p.emulatedSeconds;
  EXPECT_NEAR(phaseSum, s.emulatedSeconds, 1e-9 * s.emulatedSeconds);
  EXPECT_GT(s.counts.router.messages, 0);
  EXPECT_GT(s.counts.sort.ops, 0);
  const auto routeA = std::find_if(s.phases.begin(), s.phases.end(), [](const auto& p) { return p.name == "route (a)"; });
  ASSERT_NE(routeA, s.phases.end());
  EXPECT_EQ(routeA->counts.router.messages, projected);  // one description each
  // Every consumer gets the same through the generic channel, the per-PE lists left out; the
  // native back end has no machine of its own to report on.
  const std::shared_ptr<const ShotStats> generic = mesh.lastShotStats();
  ASSERT_NE(generic, nullptr);
  EXPECT_EQ(generic->machine, "emulated MP-1");
  EXPECT_EQ(generic->machineSeconds, s.emulatedSeconds);
  EXPECT_EQ(generic->figures.at("depth_a_max").get<int>(), s.depthAMax);
  EXPECT_EQ(generic->figures.at("depth_b_hist").get<std::vector<int>>(), s.depthBHist);
  EXPECT_EQ(generic->figures.at("passes").get<int>(), s.passes);
  EXPECT_EQ(generic->figures.at("phases").size(), s.phases.size());
  EXPECT_EQ(generic->figures.at("op_counts").at("router").at("messages").get<std::int64_t>(), s.counts.router.messages);
  EXPECT_FALSE(generic->figures.contains("depth_a"));
  EXPECT_EQ(NativeBackend(c.scene, c.patches, o).lastShotStats(), nullptr);
}

TEST(MeshBackend, ThreadCountDoesNotChangeABit) {
  const Meshed& m = builtin("two-rooms");
  MeshBackend one(m.scene, m.patches, planeOptions(64, 1));
  MeshBackend two(m.scene, m.patches, planeOptions(64, 2));
  const std::vector<int> shooters = someShooters(m, 2);
  std::vector<FormFactorRow> a, b;
  one.computeRows(shooters, a);
  two.computeRows(shooters, b);
  for (std::size_t s = 0; s < a.size(); ++s) {
    EXPECT_EQ(a[s].receivers, b[s].receivers);
    EXPECT_EQ(a[s].formFactors, b[s].formFactors);
  }
  EXPECT_EQ(one.lastShot().counts.summary(), two.lastShot().counts.summary());
}

TEST(MeshBackend, SelectsShootersAsTheSolverDoesWithReduceMax) {
  const Meshed& m = builtin("cornell");
  MeshBackend mesh(m.scene, m.patches, planeOptions(64));
  const int n = static_cast<int>(m.patches.size());
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> level(0, 5);  // few levels: many ties
  std::vector<double> power(n);
  for (double& p : power) p = level(rng) * 0.25;
  const std::vector<int> rank = depthTieRanks(m.patches);
  std::vector<int> expected(n);
  std::iota(expected.begin(), expected.end(), 0);
  std::erase_if(expected, [&](int j) { return !(power[j] > 0.0); });
  std::sort(expected.begin(), expected.end(), [&](int a, int b) {
    return power[a] != power[b] ? power[a] > power[b] : rank[a] < rank[b];
  });
  expected.resize(5);
  EXPECT_EQ(mesh.selectShooters(power, rank, 5), expected);
  NativeBackend native(m.scene, m.patches, planeOptions(64));
  EXPECT_EQ(native.selectShooters(power, rank, 5), expected);
  // Charged, and the start of the iteration's record.
  EXPECT_GT(mesh.machine().costs().reduce.ops, 0);
  ASSERT_EQ(mesh.lastShot().phases.size(), 1u);
  EXPECT_EQ(mesh.lastShot().phases[0].name, "shooter selection");
  EXPECT_EQ(mesh.lastShot().counts.reduce.ops, 5);
  EXPECT_GT(mesh.lastShot().emulatedSeconds, 0.0);
  // A NaN power is an error on the mesh as on the host, not a patch passed over.
  power[7] = std::numeric_limits<double>::quiet_NaN();
  for (FormFactorBackend* backend : {static_cast<FormFactorBackend*>(&mesh), static_cast<FormFactorBackend*>(&native)})
    try {
      backend->selectShooters(power, rank, 5);
      ADD_FAILURE() << "a NaN unshot power was passed over";
    } catch (const SolveError& e) {
      EXPECT_NE(std::string(e.what()).find("patch 7 has a NaN unshot power"), std::string::npos) << e.what();
    }
}

// The emulated time of a solver iteration covers all of it: the reduceMax that picks the
// shooters, the shot, and the radiosity update on the PEs holding the receivers.
TEST(MeshBackend, AnIterationIsChargedForSelectionShotAndUpdate) {
  const Meshed& m = builtin("cornell");
  SolveOptions o = planeOptions(64);
  o.shooters = 2;
  o.maxIterations = 3;
  ProgressiveSolver solver(m.scene, m.patches, o);
  while (!solver.done()) {
    const IterationRecord& record = solver.step();
    const MeshShotStats& shot = dynamic_cast<MeshBackend&>(solver.backend()).lastShot();
    ASSERT_NE(record.shotStats, nullptr);
    EXPECT_EQ(record.shotStats->machineSeconds, shot.emulatedSeconds);  // the record is the iteration's
    const std::vector<MeshPhaseCost>& phases = shot.phases;
    const auto shooters = static_cast<std::int64_t>(record.shooters.size());
    ASSERT_GE(phases.size(), 3u);
    EXPECT_EQ(phases.front().name, "shooter selection");
    // One reduceMax per shooter, and one more that finds none when fewer than k have power.
    EXPECT_EQ(phases.front().counts.reduce.ops, shooters + (shooters < o.shooters ? 1 : 0));
    EXPECT_EQ(phases.back().name, "radiosity update");
    EXPECT_EQ(phases.back().counts.reduce.ops, shooters);  // one reduceAdd of absorbed power per row
    EXPECT_GT(phases.back().counts.alu.flops, 0.0);
    EXPECT_GT(phases.back().emulatedSeconds, 0.0);
    double sum = 0.0;
    for (const MeshPhaseCost& p : phases) sum += p.emulatedSeconds;
    EXPECT_NEAR(sum, shot.emulatedSeconds, 1e-9 * sum) << "iteration " << record.iteration;
  }
  EXPECT_EQ(solver.history().back().shooters.size(), 2u);
}

TEST(MeshBackend, RefusesOtherProjectionsAndMeshesThatCannotSort) {
  const Meshed& m = builtin("cornell");
  SolveOptions o = planeOptions(64);
  o.projection = Projection::Hemicube;
  EXPECT_THROW(MeshBackend(m.scene, m.patches, o), OptionError);
  MeshBackendOptions oddMesh;
  oddMesh.peRows = 48;
  EXPECT_THROW(MeshBackend(m.scene, m.patches, planeOptions(64), oddMesh), OptionError);
}

TEST(MeshBackend, ScanConvertsInPassesWhenDescriptionsOverflowPeMemory) {
  const Meshed& m = builtin("office");
  const int one[] = {someShooters(m, 1)[0]};
  std::vector<FormFactorRow> roomy, tight;
  MeshBackend big(m.scene, m.patches, planeOptions(64));
  big.computeRows(one, roomy);
  ASSERT_EQ(big.lastShot().passes, 1);
  MeshBackendOptions small;
  small.memoryBudgetBytes = 1024;  // room for a dozen descriptions per PE
  MeshBackend mesh(m.scene, m.patches, planeOptions(64), small);
  mesh.computeRows(one, tight);
  EXPECT_GT(mesh.lastShot().passes, 1);
  EXPECT_LE(mesh.lastShot().counts.memoryHighWaterBytes, 1024);
  EXPECT_EQ(mesh.lastShot().depthA, big.lastShot().depthA);  // the same arrivals, over the passes
  EXPECT_EQ(mesh.lastShot().depthB, big.lastShot().depthB);
  expectSameRow(tight[0], roomy[0], 1e-12);
}

// Larger machines (--pe-grid) lay the same plane over more PEs: at 128 x 128 one pixel each, at
// 256 x 256 one pixel on one PE in four. Each pixel is still decided by the same set-up and
// z-compare, so the item buffer is the native one; the form factors are summed in another order.
TEST(MeshBackend, LargerMachinesGiveTheNativeItemBuffer) {
  const Meshed& m = builtin("cornell");
  SolveOptions o = planeOptions(128);
  NativeBackend native(m.scene, m.patches, o);
  const int one[] = {someShooters(m, 1)[0]};
  const ItemBuffer reference = native.singlePlaneItemBuffer(one[0]);
  std::vector<FormFactorRow> nativeRows, meshRows;
  native.computeRows(one, nativeRows);
  for (int side : {64, 128, 256}) {
    o.machine = {side, side, 16};
    MeshBackend mesh(m.scene, m.patches, o, meshBackendOptions(o));
    ASSERT_EQ(mesh.machine().size(), side * side);
    EXPECT_TRUE(sameItemBuffer(mesh.singlePlaneItemBuffer(one[0]), reference)) << side << " x " << side;
    mesh.computeRows(one, meshRows);
    expectSameRow(meshRows[0], nativeRows[0], 1e-9);
  }
}

// --pe-memory reaches the machine: a budget too small for one pass's descriptions takes more
// passes, with the same arrivals, item buffer and form factors.
TEST(MeshBackend, LessPeMemoryTakesMorePassesForTheSameResult) {
  const Meshed& m = builtin("office");
  const int one[] = {someShooters(m, 1)[0]};
  SolveOptions o = planeOptions(128);
  o.machine = {128, 128, 16};
  const auto roomy = makeFormFactorBackend(m.scene, m.patches, o);
  o.machine.memoryKb = 1;
  const auto tight = makeFormFactorBackend(m.scene, m.patches, o);
  std::vector<FormFactorRow> roomyRows, tightRows;
  roomy->computeRows(one, roomyRows);
  tight->computeRows(one, tightRows);
  const MeshShotStats& r = dynamic_cast<MeshBackend&>(*roomy).lastShot();
  const MeshShotStats& t = dynamic_cast<MeshBackend&>(*tight).lastShot();
  EXPECT_EQ(r.passes, 1);
  EXPECT_GT(t.passes, 1);
  EXPECT_LE(t.counts.memoryHighWaterBytes, 1024);
  EXPECT_EQ(t.depthA, r.depthA);
  EXPECT_EQ(t.depthB, r.depthB);
  EXPECT_TRUE(sameItemBuffer(tight->singlePlaneItemBuffer(one[0]), roomy->singlePlaneItemBuffer(one[0])));
  EXPECT_EQ(tightRows[0].receivers, roomyRows[0].receivers);
  EXPECT_EQ(tightRows[0].formFactors, roomyRows[0].formFactors);
}

TEST(MeshBackend, PatchesThatDoNotFitAreAClearError) {
  const Meshed& m = builtin("office");
  MeshBackendOptions tiny;
  tiny.memoryBudgetBytes = 100;  // less than one patch record
  try {
    MeshBackend mesh(m.scene, m.patches, planeOptions(64), tiny);
    FAIL() << "expected an OptionError";
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("PE (row 0, col 0)"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'patches'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("per-PE budget is 100 bytes. Fix: give each PE more memory (a larger --pe-memory KB)"),
              std::string::npos) << e.what();
  }
}

// After a split the elements lie cyclically in their new order: each one whose PE changes is one
// router message, in as many sends as the busiest PE makes elements; the rows and item buffers
// are then the native back end's over the split elements.
TEST(MeshBackend, ASplitRoutesEachMovedElementToItsNewPe) {
  const Meshed& m = builtin("cornell");
  Elements elements = patchesAsElements(m.patches);
  const SolveOptions o = planeOptions(64);
  const MeshBackendOptions small{MappingKind::Hierarchical, 8, 8, 16 * 1024};
  MeshBackend mesh(m.scene, m.patches, elements.elements, o, small);
  std::vector<char> split(elements.elements.size(), 0);
  for (std::size_t e = 0; e < split.size(); e += 7) split[e] = 1;
  const std::vector<int> origin = splitElements(elements, split);
  const emu::CostCounts before = mesh.machine().costs();
  mesh.receiversSplit(origin);
  const emu::CostCounts cost = mesh.machine().costs() - before;
  const int pes = 64;
  std::int64_t moved = 0;
  std::vector<int> made(pes, 0);
  for (std::size_t e = 0; e < origin.size(); ++e) {
    moved += origin[e] % pes != static_cast<int>(e) % pes ? 1 : 0;
    ++made[origin[e] % pes];
  }
  EXPECT_EQ(origin.size(), m.patches.size() + 3 * static_cast<std::size_t>(std::count(split.begin(), split.end(), 1)));
  EXPECT_EQ(cost.router.messages, moved);
  EXPECT_EQ(cost.router.ops, *std::max_element(made.begin(), made.end()));
  NativeBackend native(m.scene, m.patches, elements, o);
  const std::vector<int> shooters = someShooters(m, 3);
  std::vector<FormFactorRow> meshRows, nativeRows;
  mesh.computeRows(shooters, meshRows);
  native.computeRows(shooters, nativeRows);
  for (std::size_t s = 0; s < shooters.size(); ++s) {
    expectSameRow(meshRows[s], nativeRows[s], 1e-9);
    EXPECT_TRUE(sameItemBuffer(mesh.singlePlaneItemBuffer(shooters[s]), native.singlePlaneItemBuffer(shooters[s])));
  }
}

// The moving elements share the PEs' memory with the records they leave: a split that does not
// fit is the same clear error as patches that do not fit.
TEST(MeshBackend, ASplitThatDoesNotFitIsAClearError) {
  const Meshed& m = builtin("cornell");
  Elements elements = patchesAsElements(m.patches);
  const int slots = static_cast<int>((m.patches.size() + 63) / 64);
  // Room for the patches and their single elements (120 bytes a record), not for four times as many.
  const MeshBackendOptions tight{MappingKind::Hierarchical, 8, 8, 2 * 120 * slots + 100};
  MeshBackend mesh(m.scene, m.patches, elements.elements, planeOptions(64), tight);
  const std::vector<int> origin = splitElements(elements, std::vector<char>(elements.elements.size(), 1));
  try {
    mesh.receiversSplit(origin);
    FAIL() << "expected an OptionError";
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("'elements in transit'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("a larger --pe-memory KB"), std::string::npos) << e.what();
  }
}

// Eq. 1.2 by hand over both back ends' rows, shooters chosen on the mesh by reduceMax: the same
// radiosity to 1e-6 relative after 30 shots.
TEST(MeshBackend, ShootingWithItsRowsGivesTheNativeRadiosity) {
  const Meshed& m = builtin("office");
  const SolveOptions o = planeOptions(64);
  MeshBackend mesh(m.scene, m.patches, o);
  NativeBackend native(m.scene, m.patches, o);
  const int n = static_cast<int>(m.patches.size());
  const std::vector<int> rank = depthTieRanks(m.patches);
  struct Run {
    FormFactorBackend* backend;
    std::vector<Rgb> b, unshot;
  };
  std::vector<Run> runs = {{&mesh, {}, {}}, {&native, {}, {}}};
  for (Run& r : runs)
    for (const Patch& p : m.patches) {
      r.b.push_back(m.scene.materials[p.material].emittance);
      r.unshot.push_back(r.b.back());
    }
  for (int iteration = 0; iteration < 30; ++iteration)
    for (Run& r : runs) {
      std::vector<double> powerW(n);
      for (int j = 0; j < n; ++j) powerW[j] = (r.unshot[j].r + r.unshot[j].g + r.unshot[j].b) * m.patches[j].areaM2;
      const std::vector<int> shooter = mesh.selectShooters(powerW, rank, 1);
      ASSERT_EQ(shooter.size(), 1u);
      std::vector<FormFactorRow> rows;
      r.backend->computeRows(shooter, rows);
      const int i = shooter[0];
      for (std::size_t k = 0; k < rows[0].receivers.size(); ++k) {
        const int j = rows[0].receivers[k];
        const Rgb gain = m.scene.materials[m.patches[j].material].rho * r.unshot[i] *
                         (rows[0].formFactors[k] * m.patches[i].areaM2 / m.patches[j].areaM2);
        r.b[j] += gain;
        r.unshot[j] += gain;
      }
      r.unshot[i] = Rgb(0.0);
    }
  for (int j = 0; j < n; ++j)
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(runs[0].b[j][c], runs[1].b[j][c], 1e-6 * runs[1].b[j][c]) << "patch " << j;
}

}  // namespace
}  // namespace radmesh
