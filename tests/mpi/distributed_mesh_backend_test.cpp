// The mesh back end with its machine split over the run's processes (SolveOptions::meshTransport)
// equals the back end in one process bit for bit: the item buffers, the form-factor rows, the
// shot's depths at (a) and (b) and its cost counts, and a whole solve (shooter selection and
// radiosity update included).
#include "solver/backends/mesh/mesh_backend.h"

#include <gtest/gtest.h>

#include <memory>

#include "emulator/mpi/mpi_transport.h"
#include "solver/radiosity/progressive_solver.h"
#include "solver/scene/scene_error.h"
#include "tests/solver/backends/mesh/mesh_agreement.h"

namespace radmesh {
namespace {

// Small enough to run under ASan on 4 ranks: 16 x 16 PEs (blocks of 8 x 16 or 8 x 8), 32 x 32 pixels.
SolveOptions smallMachine(MappingKind mapping) {
  SolveOptions o;
  o.backend = Backend::Mesh;
  o.projection = Projection::Plane;
  o.mapping = mapping;
  o.resolution = 32;
  o.threads = 1;
  o.machine = {16, 16, 16};
  return o;
}

SolveOptions split(SolveOptions o) {
  o.meshTransport = std::make_shared<emu::MpiTransport>();
  return o;
}

const test::MeshedScene& cornell() {
  static const test::MeshedScene m = test::meshedScene("cornell");
  return m;
}

void expectSameCounts(const emu::CostCounts& a, const emu::CostCounts& b, const std::string& what) {
  EXPECT_EQ(a.summary(), b.summary()) << what;  // every class's counts but host seconds
  EXPECT_EQ(a.maxCollisions, b.maxCollisions) << what;
  EXPECT_EQ(a.memoryHighWaterBytes, b.memoryHighWaterBytes) << what;
}

void expectSameShot(const MeshShotStats& a, const MeshShotStats& b) {
  EXPECT_EQ(a.depthA, b.depthA);
  EXPECT_EQ(a.depthB, b.depthB);
  EXPECT_EQ(a.passes, b.passes);
  EXPECT_EQ(a.depthAMax, b.depthAMax);
  EXPECT_EQ(a.depthBMax, b.depthBMax);
  EXPECT_EQ(a.depthAHist, b.depthAHist);
  EXPECT_EQ(a.depthBHist, b.depthBHist);
  expectSameCounts(a.counts, b.counts, "the shot");
  ASSERT_EQ(a.phases.size(), b.phases.size());
  for (size_t p = 0; p < a.phases.size(); ++p) {
    EXPECT_EQ(a.phases[p].name, b.phases[p].name);
    expectSameCounts(a.phases[p].counts, b.phases[p].counts, a.phases[p].name);
  }
}

class DistributedMeshBackend : public ::testing::TestWithParam<MappingKind> {};

// Three shooters one by one, then two in one shot (two planes on the mesh at once).
TEST_P(DistributedMeshBackend, ShotsEqualOneProcessPixelForPixel) {
  const test::MeshedScene& m = cornell();
  const SolveOptions o = smallMachine(GetParam());
  MeshBackend alone(m.scene, m.patches, o, meshBackendOptions(o));
  MeshBackend spread(m.scene, m.patches, split(o), meshBackendOptions(o));
  ASSERT_TRUE(spread.machine().distributed());
  const std::vector<int> shooters = test::someShooters(m.scene, m.patches, 3);
  for (int shooter : shooters) {
    const ItemBuffer a = alone.singlePlaneItemBuffer(shooter), b = spread.singlePlaneItemBuffer(shooter);
    EXPECT_EQ(b.items, a.items) << "shooter " << shooter;
    EXPECT_EQ(b.inverseDepth, a.inverseDepth) << "shooter " << shooter;
    EXPECT_GT(std::count_if(a.items.begin(), a.items.end(), [](int i) { return i != ItemBuffer::kNone; }), 100);
  }
  for (const std::vector<int>& shot : {std::vector<int>{shooters[0]}, std::vector<int>{shooters[1], shooters[2]}}) {
    std::vector<FormFactorRow> a, b;
    alone.computeRows(shot, a);
    spread.computeRows(shot, b);
    ASSERT_EQ(a.size(), shot.size());
    ASSERT_EQ(b.size(), a.size());
    for (size_t q = 0; q < a.size(); ++q) {
      EXPECT_EQ(b[q].receivers, a[q].receivers);
      EXPECT_EQ(b[q].formFactors, a[q].formFactors);
      EXPECT_FALSE(a[q].receivers.empty());
    }
    expectSameShot(alone.lastShot(), spread.lastShot());
    EXPECT_EQ(static_cast<int>(spread.lastShot().depthA.size()), 16 * 16);
    EXPECT_GT(spread.lastShot().depthAMax, 0);
  }
  expectSameCounts(alone.machine().costs(), spread.machine().costs(), "the machine");
}

INSTANTIATE_TEST_SUITE_P(Mappings, DistributedMeshBackend,
                         ::testing::Values(MappingKind::Hierarchical, MappingKind::Adaptive),
                         [](const auto& info) { return std::string(toString(info.param)) == "adaptive" ? "Adaptive" : "Hierarchical"; });

// Three iterations of two shooters: the shooters the mesh selects, the radiosity every process
// keeps (each updates the others' receivers too) and the ledger.
TEST(DistributedMeshSolve, ThreeIterationsEqualOneProcess) {
  const test::MeshedScene& m = cornell();
  SolveOptions o = smallMachine(MappingKind::Hierarchical);
  o.shooters = 2;
  o.maxIterations = 3;
  ProgressiveSolver alone(m.scene, m.patches, o);
  ProgressiveSolver spread(m.scene, m.patches, split(o));
  while (!alone.done()) alone.step();
  while (!spread.done()) spread.step();
  ASSERT_EQ(spread.history().size(), 3u);
  ASSERT_EQ(alone.history().size(), 3u);
  for (size_t i = 0; i < 3; ++i) EXPECT_EQ(spread.history()[i].shooters, alone.history()[i].shooters) << i;
  EXPECT_EQ(spread.radiosity(), alone.radiosity());
  EXPECT_EQ(spread.ledger().absorbed, alone.ledger().absorbed);
  EXPECT_EQ(spread.ledger().unshot, alone.ledger().unshot);
}

// A rank grid that would cut the 4 x 4 router clusters is refused naming --pe-grid.
TEST(DistributedMeshSolve, ABlockOfPartClustersIsRefused) {
  SolveOptions o = split(smallMachine(MappingKind::Hierarchical));
  o.machine = {4, 4, 16};
  const test::MeshedScene& m = cornell();
  if (o.meshTransport->rankGrid().size() == 1) {
    EXPECT_NO_THROW(MeshBackend(m.scene, m.patches, o, meshBackendOptions(o)));
    return;
  }
  try {
    MeshBackend(m.scene, m.patches, o, meshBackendOptions(o));
    FAIL() << "a 4 x 4 machine split over processes";
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("blocks of whole 4 x 4 clusters"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--pe-grid"), std::string::npos) << e.what();
  }
}

// Adaptive elements move between PEs at a split, into lists other processes hold (the router
// carries them across): the same splits, elements and light as one process, bit for bit.
TEST(DistributedMeshSolve, AdaptiveSplitsEqualOneProcess) {
  const test::MeshedScene& m = cornell();
  SolveOptions o = smallMachine(MappingKind::Hierarchical);
  o.subdivide = Subdivide::Adaptive;
  o.minElementM = 0.05;
  o.maxIterations = 6;
  ProgressiveSolver alone(m.scene, m.patches, o);
  ProgressiveSolver spread(m.scene, m.patches, split(o));
  while (!alone.done()) alone.step();
  while (!spread.done()) spread.step();
  ASSERT_GT(alone.elements().size(), m.patches.size());  // it split
  ASSERT_EQ(spread.elements().size(), alone.elements().size());
  for (size_t e = 0; e < alone.elements().size(); ++e)
    EXPECT_EQ(spread.elements()[e].vertices, alone.elements()[e].vertices) << "element " << e;
  EXPECT_EQ(spread.elementRadiosity(), alone.elementRadiosity());
  EXPECT_EQ(spread.radiosity(), alone.radiosity());
  EXPECT_EQ(spread.ledger().absorbed, alone.ledger().absorbed);
  EXPECT_EQ(spread.ledger().unshot, alone.ledger().unshot);
  const auto counts = [](ProgressiveSolver& solver) {
    return dynamic_cast<MeshBackend&>(solver.backend()).machine().costs().summary();
  };
  EXPECT_EQ(counts(spread), counts(alone));
}

}  // namespace
}  // namespace radmesh
