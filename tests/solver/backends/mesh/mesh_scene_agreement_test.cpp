// The mesh back end against the native one on every built-in and shared scene: the same
// single-plane item buffers for several shooters, and the same radiosity to 1e-6 relative after
// some iterations; and every plane mapping runs on every shared scene without changing B.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "solver/backends/mesh/mesh_backend.h"
#include "solver/backends/native/native_backend.h"
#include "solver/radiosity/progressive_solver.h"
#include "tests/solver/backends/mesh/mesh_agreement.h"
#include "tests/solver/solver_test_helpers.h"
#include "tests/test_paths.h"

namespace radmesh {
namespace {

struct SceneCase {
  std::string name;    // test name; the built-in's name when `shared` is empty
  std::string shared;  // path under ../shared
  int iterations;      // shots for the radiosity comparison: enough to bounce, few enough for ASan
};

std::ostream& operator<<(std::ostream& os, const SceneCase& c) { return os << c.name; }

const SceneCase kBuiltins[] = {
    {"office", "", 20}, {"cornell", "", 40}, {"furnace", "", 40}, {"two-rooms", "", 30}};
const SceneCase kShared[] = {{"cube", "scenes/mgf/cube.mgf", 30},
                             {"corridor", "scenes/mgf/corridor.mgf", 20},
                             {"examp1", "scenes/mgf/examp1.mgf", 30},
                             {"office2", "scenes/mgf/office2/office2.mgf", 12},
                             {"office3", "scenes/mgf/office3/office.mgf", 9}};

using Meshed = test::MeshedScene;

SolveOptions planeOptions(Backend backend, int resolution, int iterations) {
  SolveOptions o = test::fixedIterations(test::optionsFor(Projection::Plane, resolution, 2), iterations);
  o.backend = backend;
  return o;
}

// Steps to the options' iteration count, checking the ledger at every iteration.
std::unique_ptr<ProgressiveSolver> solved(const Meshed& m, const SolveOptions& o) {
  auto solver = std::make_unique<ProgressiveSolver>(m.scene, m.patches, o);
  EXPECT_TRUE(test::solveChecked(*solver)) << toString(o.backend) << " " << toString(o.mapping);
  EXPECT_EQ(static_cast<int>(solver->history().size()), o.maxIterations) << "stopped early: nothing left to shoot";
  return solver;
}

class MeshSceneAgreement : public ::testing::TestWithParam<SceneCase> {};

#define RADMESH_LOAD_CASE(m, c)                          \
  std::string where = (c).name;                          \
  if (!(c).shared.empty()) {                             \
    RADMESH_REQUIRE_SHARED(path, (c).shared);            \
    where = path.string();                               \
  }                                                      \
  const Meshed m = test::meshedScene(where)

TEST_P(MeshSceneAgreement, ItemBuffersAreTheNativeOnes) {
  RADMESH_LOAD_CASE(m, GetParam());
  for (int resolution : {64, 128, 256}) {  // the paper's resolutions
    const SolveOptions o = planeOptions(Backend::Mesh, resolution, 1);
    NativeBackend native(m.scene, m.patches, o);
    MeshBackend mesh(m.scene, m.patches, o);
    const int n = static_cast<int>(m.patches.size());
    for (int candidate : test::someShooters(m.scene, m.patches, 3)) {
      // From each spread-out start, the first patch that sees something (a patch facing out of
      // an open scene sees nothing: an empty comparison).
      auto sees = [](const ItemBuffer& b) { return std::any_of(b.items.begin(), b.items.end(), [](int i) { return i >= 0; }); };
      int shooter = candidate;
      ItemBuffer expected = native.singlePlaneItemBuffer(shooter);
      for (int tries = 1; tries < n && !sees(expected); ++tries)
        expected = native.singlePlaneItemBuffer(shooter = (candidate + tries) % n);
      ASSERT_TRUE(sees(expected)) << "no patch sees anything";
      EXPECT_TRUE(test::sameItemBuffer(mesh.singlePlaneItemBuffer(shooter), expected))
          << GetParam().name << " at " << resolution << ", shooter " << shooter;
    }
  }
}

TEST_P(MeshSceneAgreement, RadiosityAgreesWithNativeTo1e6) {
  RADMESH_LOAD_CASE(m, GetParam());
  const auto native = solved(m, planeOptions(Backend::Native, 64, GetParam().iterations));
  const auto mesh = solved(m, planeOptions(Backend::Mesh, 64, GetParam().iterations));
  EXPECT_TRUE(test::sameRadiosity(mesh->radiosity(), native->radiosity(), 1e-6)) << GetParam().name;
}

const auto caseName = [](const ::testing::TestParamInfo<SceneCase>& info) {
  std::string s = info.param.name;
  std::replace(s.begin(), s.end(), '-', '_');
  return s;
};

INSTANTIATE_TEST_SUITE_P(Builtin, MeshSceneAgreement, ::testing::ValuesIn(kBuiltins), caseName);
INSTANTIATE_TEST_SUITE_P(Shared, MeshSceneAgreement, ::testing::ValuesIn(kShared), caseName);

// At 128^2 each PE holds 2 x 2 pixels, so the mappings lay the plane out differently (at 64^2 they
// coincide); how the pixels are laid out must change the cost, never the answer.
class MeshMappingsOnShared : public ::testing::TestWithParam<SceneCase> {};

TEST_P(MeshMappingsOnShared, EveryMappingRunsWithTheHierarchicalRadiosity) {
  RADMESH_LOAD_CASE(m, GetParam());
  const int iterations = std::max(3, GetParam().iterations / 3);
  SolveOptions o = planeOptions(Backend::Mesh, 128, iterations);
  const auto hierarchical = solved(m, o);
  for (MappingKind mapping : {MappingKind::CutAndStack, MappingKind::Adaptive}) {
    o.mapping = mapping;
    const auto other = solved(m, o);
    EXPECT_TRUE(test::sameRadiosity(other->radiosity(), hierarchical->radiosity(), 1e-6)) << toString(mapping);
    // The shots ran on the mesh with this mapping: adaptive has its own phase.
    for (const IterationRecord& record : other->history()) {
      ASSERT_NE(record.shotStats, nullptr) << toString(mapping) << " iteration " << record.iteration;
      const auto& phases = record.shotStats->figures.at("phases");
      const bool adaptivePhase = std::any_of(phases.begin(), phases.end(),
                                             [](const nlohmann::json& p) { return p["name"] == "adaptive mapping"; });
      EXPECT_EQ(adaptivePhase, mapping == MappingKind::Adaptive) << toString(mapping);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Shared, MeshMappingsOnShared, ::testing::ValuesIn(kShared), caseName);

}  // namespace
}  // namespace radmesh
