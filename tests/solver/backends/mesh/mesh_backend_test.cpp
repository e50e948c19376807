// The mesh back end against the native one: the same item buffers pixel for pixel, the same form
// factors up to summation order, and load-balance depths that are counts of what arrived.
#include "solver/backends/mesh/mesh_backend.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <random>

#include "emulator/memory_ledger.h"
#include "solver/backends/native/native_backend.h"
#include "solver/radiosity/progressive_solver.h"
#include "solver/scene/scene_error.h"
#include "tests/solver/backends/mesh/mesh_agreement.h"

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

TEST(MeshBackend, DepthsCountWhatArrivedAtEachPe) {
  const Meshed& m = builtin("office");
  const SolveOptions o = planeOptions(128);
  MeshBackend mesh(m.scene, m.patches, o);
  NativeBackend native(m.scene, m.patches, o);
  const int shooter = someShooters(m, 1)[0];
  std::vector<FormFactorRow> rows;
  const int one[] = {shooter};
  mesh.computeRows(one, rows);
  const MeshShotStats& s = mesh.lastShot();
  // Recount from the native item buffer's patches: every projected patch arrives once at (a),
  // and at (b) once per PE row its strip covers (128 pixel rows in blocks of 2 per PE row).
  ASSERT_EQ(s.depthA.size(), 4096u);
  long long arrivedA = 0, arrivedB = 0;
  for (int d : s.depthA) arrivedA += d;
  for (int d : s.depthB) arrivedB += d;
  EXPECT_GT(arrivedA, 100);
  EXPECT_GT(arrivedB, arrivedA);
  EXPECT_EQ(s.depthAMax, *std::max_element(s.depthA.begin(), s.depthA.end()));
  EXPECT_EQ(static_cast<int>(s.depthAHist.size()), s.depthAMax + 1);
  int pes = 0;
  for (int h : s.depthBHist) pes += h;
  EXPECT_EQ(pes, 4096);
  // The same projected patches the native back end rasterised, counted from the form factors of
  // the phases: a patch that shows anywhere was projected, so arrived at (a).
  EXPECT_GE(arrivedA, static_cast<long long>(rows[0].receivers.size()));
  EXPECT_GT(s.emulatedSeconds, 0.0);
  double phaseSum = 0.0;
  for (const MeshPhaseCost& p : s.phases) phaseSum += p.emulatedSeconds;
  EXPECT_NEAR(phaseSum, s.emulatedSeconds, 1e-9 * s.emulatedSeconds);
  EXPECT_GT(s.counts.router.messages, 0);
  EXPECT_GT(s.counts.sort.ops, 0);
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
  EXPECT_EQ(native.lastShotStats(), nullptr);
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
  EXPECT_GT(mesh.machine().costs().reduce.ops, 0);
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

TEST(MeshBackend, PatchesThatDoNotFitAreAClearError) {
  const Meshed& m = builtin("office");
  MeshBackendOptions tiny;
  tiny.memoryBudgetBytes = 100;  // less than one patch record
  try {
    MeshBackend mesh(m.scene, m.patches, planeOptions(64), tiny);
    FAIL() << "expected a MemoryBudgetError";
  } catch (const emu::MemoryBudgetError& e) {
    EXPECT_NE(std::string(e.what()).find("PE (row 0, col 0)"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'patches'"), std::string::npos) << e.what();
    EXPECT_EQ(e.budgetBytes(), 100);
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
