#include "solver/radiosity/checkpoint.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>

#include "solver/cells/find_cells.h"
#include "solver/io/scene_loader.h"
#include "solver/meshing/meshing.h"
#include "solver/scene/scene_error.h"
#include "tests/solver/io/gltf_test_file.h"
#include "tests/solver/solver_test_helpers.h"

namespace radmesh {
namespace {

using test::TempDir;

struct ScenePatches {
  Scene scene;
  std::vector<Patch> patches;
};

ScenePatches cornell(double cellM = 0.381) {
  ScenePatches m{loadScene("cornell"), {}};
  m.patches = meshScene(m.scene, cellM);
  return m;
}

SolveOptions options(Backend backend, int iterations) {
  SolveOptions o = test::fixedIterations(test::optionsFor(Projection::Plane, 64, 2), iterations);
  o.backend = backend;
  o.shooters = 2;
  o.formFactorCacheBytes = 64 << 20;  // the cache goes on as it was: the same rows served after the stop
  return o;
}

std::unique_ptr<ProgressiveSolver> solvedToDone(const ScenePatches& m, const SolveOptions& o) {
  auto solver = std::make_unique<ProgressiveSolver>(m.scene, m.patches, o);
  while (!solver->done()) solver->step();
  return solver;
}

bool bitwiseEqual(const std::vector<Rgb>& a, const std::vector<Rgb>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Rgb)) == 0;
}

std::string readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// Stops after `first` iterations, checkpoints, resumes in a new solver and goes on to `total`:
// bitwise the solve that never stopped.
// The figures but the host's wall time, which no two runs share.
nlohmann::json withoutHostSeconds(nlohmann::json figures) {
  if (figures.is_object()) {
    figures.erase("host_seconds");
    for (auto& [key, value] : figures.items()) value = withoutHostSeconds(value);
  } else if (figures.is_array()) {
    for (auto& value : figures) value = withoutHostSeconds(value);
  }
  return figures;
}

void expectResumeIsBitwiseStraight(Backend backend, int first, int total, Subdivide subdivide = Subdivide::Off,
                                   bool regatherAll = false) {
  TempDir dir;
  const auto path = (dir / "solve.ckpt").string();
  const ScenePatches m = cornell();
  auto optionsTo = [&](int iterations) {
    SolveOptions o = options(backend, iterations);
    if (subdivide == Subdivide::Off) return o;
    o = test::subdivided(o, subdivide, subdivide == Subdivide::Adaptive ? 0.05 : 0.2);
    o.splitContrast = 0.05;
    o.splitRegatherAll = regatherAll;
    return o;
  };
  const auto straight = solvedToDone(m, optionsTo(total));
  ASSERT_EQ(static_cast<int>(straight->history().size()), total);
  writeCheckpoint(path, *solvedToDone(m, optionsTo(first)));

  ProgressiveSolver resumed(m.scene, m.patches, optionsTo(total));
  resumeFromCheckpoint(path, resumed);
  ASSERT_EQ(static_cast<int>(resumed.history().size()), first);
  while (!resumed.done()) resumed.step();

  ASSERT_EQ(resumed.history().size(), straight->history().size());
  EXPECT_TRUE(bitwiseEqual(resumed.radiosity(), straight->radiosity()));
  EXPECT_TRUE(bitwiseEqual(resumed.displayRadiosity(), straight->displayRadiosity()));
  ASSERT_EQ(resumed.elements().size(), straight->elements().size());
  EXPECT_EQ(std::memcmp(resumed.elements().data(), straight->elements().data(), sizeof(Patch) * resumed.elements().size()), 0);
  EXPECT_TRUE(bitwiseEqual(resumed.elementRadiosity(), straight->elementRadiosity()));
  EXPECT_EQ(std::memcmp(&resumed.ledger(), &straight->ledger(), sizeof(Ledger)), 0);
  for (size_t i = 0; i < straight->history().size(); ++i) {
    const IterationRecord& a = resumed.history()[i];
    const IterationRecord& b = straight->history()[i];
    EXPECT_EQ(a.shooters, b.shooters) << "iteration " << i + 1;
    EXPECT_EQ(a.convergence, b.convergence) << "iteration " << i + 1;
    EXPECT_EQ(a.reusedRowsTotal, b.reusedRowsTotal) << "iteration " << i + 1;
    EXPECT_EQ(a.cacheHits, b.cacheHits) << "iteration " << i + 1;
    EXPECT_EQ(a.elementsSplit, b.elementsSplit) << "iteration " << i + 1;
    ASSERT_EQ(a.shotStats != nullptr, b.shotStats != nullptr) << "iteration " << i + 1;
    // The emulated machine goes on from its saved counts: each shot costs bitwise the same.
    if (a.shotStats && b.shotStats) {
      EXPECT_EQ(a.shotStats->machineSeconds, b.shotStats->machineSeconds) << "iteration " << i + 1;
      EXPECT_EQ(withoutHostSeconds(a.shotStats->figures).dump(), withoutHostSeconds(b.shotStats->figures).dump())
          << "iteration " << i + 1;
    }
  }
  int hitsAfterTheStop = 0, splitBefore = 0, splitAfter = 0;
  for (int i = 0; i < total; ++i) (i < first ? splitBefore : splitAfter) += straight->history()[i].elementsSplit;
  for (int i = first; i < total; ++i) hitsAfterTheStop += straight->history()[i].cacheHits;
  if (subdivide != Subdivide::Adaptive) {  // a split drops the rows reaching split elements
    EXPECT_GT(hitsAfterTheStop, 0) << "no row served from the cache after the stop: the saved cache untested";
  }
  if (subdivide == Subdivide::Adaptive) {  // the saved tree is split further after the stop
    EXPECT_GT(splitBefore, 0) << "after " << splitAfter;
    EXPECT_GT(splitAfter, 0) << "before " << splitBefore;
  }
}

TEST(Checkpoint, NativeResumeIsBitwiseTheStraightSolve) { expectResumeIsBitwiseStraight(Backend::Native, 40, 80); }

TEST(Checkpoint, MeshResumeIsBitwiseTheStraightSolveWithTheSameEmulatedCosts) {
  expectResumeIsBitwiseStraight(Backend::Mesh, 12, 24);
}

TEST(Checkpoint, UniformElementsResumeBitwise) { expectResumeIsBitwiseStraight(Backend::Native, 20, 40, Subdivide::Uniform); }
TEST(Checkpoint, UniformElementsOnTheMeshResumeBitwise) {
  expectResumeIsBitwiseStraight(Backend::Mesh, 6, 12, Subdivide::Uniform);
}
// The split tree, the elements' radiosity and all each patch shot are saved: the resumed solve
// splits on as the straight one does.
TEST(Checkpoint, AdaptiveElementsResumeBitwise) { expectResumeIsBitwiseStraight(Backend::Native, 3, 16, Subdivide::Adaptive); }
TEST(Checkpoint, AdaptiveElementsRegatheringEveryShotResumeBitwise) {
  expectResumeIsBitwiseStraight(Backend::Native, 3, 16, Subdivide::Adaptive, true);
}

TEST(Checkpoint, WritesAtomicallyLeavingNoTemporaryFile) {
  TempDir dir;
  const ScenePatches m = cornell();
  const auto solver = solvedToDone(m, options(Backend::Native, 3));
  writeCheckpoint((dir / "a.ckpt").string(), *solver);
  writeCheckpoint((dir / "a.ckpt").string(), *solver);  // over the last one
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    EXPECT_EQ(entry.path().filename(), "a.ckpt");
    ++files;
  }
  EXPECT_EQ(files, 1);
  EXPECT_THROW(writeCheckpoint((dir / "no-such-folder" / "a.ckpt").string(), *solver), std::runtime_error);
}

// Resuming from `path` into a fresh solver of m and o is refused with a message naming the file
// and containing `says`; the solver is left as it was.
void expectRefused(const std::string& path, const ScenePatches& m, const SolveOptions& o, const std::string& says) {
  ProgressiveSolver solver(m.scene, m.patches, o);
  try {
    resumeFromCheckpoint(path, solver);
    ADD_FAILURE() << "accepted; expected: " << says;
  } catch (const SceneError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find(says), std::string::npos) << message;
    EXPECT_NE(message.find("fix:"), std::string::npos) << message;
  }
  EXPECT_TRUE(solver.history().empty());
}

class CheckpointRefusal : public ::testing::Test {
 protected:
  void SetUp() override { writeCheckpoint(path, *solvedToDone(m, options(Backend::Native, 5))); }
  TempDir dir;
  const std::string path = (dir / "solve.ckpt").string();
  const ScenePatches m = cornell();
};

TEST_F(CheckpointRefusal, OfAnotherScene) {
  const ScenePatches finer = cornell(0.2);
  ASSERT_NE(finer.patches.size(), m.patches.size());
  expectRefused(path, finer, options(Backend::Native, 10), "another meshed scene");
  ScenePatches brighter = m;  // the same patches, another emission
  for (Material& material : brighter.scene.materials) material.emittance *= 2.0;
  // The same name and count on both sides: the message says what else can differ, not "here the same".
  expectRefused(path, brighter, options(Backend::Native, 10),
                "another meshed scene (" + m.scene.source + ", " + std::to_string(m.patches.size()) +
                    " patches, placed, scaled or lit otherwise)");
}

TEST_F(CheckpointRefusal, OfOtherOptionsNamingThem) {
  SolveOptions other = options(Backend::Native, 10);
  other.resolution = 128;
  expectRefused(path, m, other, "--resolution 64 there, 128 here");
  other = test::subdivided(options(Backend::Native, 10), Subdivide::Uniform, 0.1);
  expectRefused(path, m, other, "--subdivide off there, uniform here; --min-element not used there, 0.1 here");
  other = options(Backend::Mesh, 10);
  expectRefused(path, m, other, "--backend native there, mesh here; --mapping not used there");
  other.machine.cols = other.machine.rows = 32;  // the MP-1's grid goes unlisted, so it is named
  expectRefused(path, m, other, "--pe-grid 64x64 there, 32x32 here");
  // Options that do not change the answer are free to change.
  other = options(Backend::Native, 10);
  other.threads = 1;
  other.until = 0.5;
  other.formFactorCacheBytes = 0;
  ProgressiveSolver solver(m.scene, m.patches, other);
  resumeFromCheckpoint(path, solver);
  EXPECT_EQ(solver.history().size(), 5u);
}

TEST_F(CheckpointRefusal, Truncated) {
  const std::string bytes = readBytes(path);
  writeBytes(path, bytes.substr(0, bytes.size() - 1));
  expectRefused(path, m, options(Backend::Native, 10), "is truncated");
  writeBytes(path, bytes.substr(0, 20));
  expectRefused(path, m, options(Backend::Native, 10), "is truncated");
  writeBytes(path, "");
  expectRefused(path, m, options(Backend::Native, 10), "is not a radmesh checkpoint");
  // Neither read for ever (it ran out of memory) nor waited on (a pipe with no writer).
  expectRefused("/dev/zero", m, options(Backend::Native, 10), "is not a regular file");
  const std::string fifo = (dir / "pipe.ckpt").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expectRefused(fifo, m, options(Backend::Native, 10), "is not a regular file");
}

TEST_F(CheckpointRefusal, OneFlippedByte) {
  const std::string bytes = readBytes(path);
  for (size_t at : {size_t{40}, bytes.size() / 2, bytes.size() - 1}) {
    std::string flipped = bytes;
    flipped[at] = static_cast<char>(flipped[at] ^ 0x10);
    writeBytes(path, flipped);
    expectRefused(path, m, options(Backend::Native, 10), "is corrupted");
  }
  std::string otherVersion = bytes;
  otherVersion[8] = 7;
  writeBytes(path, otherVersion);
  expectRefused(path, m, options(Backend::Native, 10), "is a version 7 checkpoint");
}

TEST(Checkpoint, RestoreRefusesAProgressOfOtherPatchesAndLeavesTheSolverAsItWas) {
  const ScenePatches m = cornell();
  auto solver = solvedToDone(m, options(Backend::Native, 3));
  SolverProgress other = solver->progress();
  other.history.back().shooters.push_back(static_cast<int>(m.patches.size()));
  EXPECT_THROW(solver->restoreProgress(other), std::invalid_argument);
  other = solver->progress();
  other.timesShot.pop_back();
  EXPECT_THROW(solver->restoreProgress(other), std::invalid_argument);
  EXPECT_EQ(solver->history().size(), 3u);
  EXPECT_EQ(solver->history().back().shooters.size(), 2u);
}

// A progress whose checksum holds but whose figures no solve makes (a checkpoint edited, its
// checksum mended) is refused before anything is restored: it resumed, printed a NaN ledger and
// wrote the bake.
TEST(Checkpoint, RestoreRefusesFiguresNoSolveMakes) {
  const ScenePatches m = cornell();
  auto solver = solvedToDone(m, options(Backend::Native, 3));
  const std::vector<std::pair<const char*, void (*)(SolverProgress&)>> edits = {
      {"radiosity", [](SolverProgress& p) { p.radiosity[0].g = std::nan(""); }},
      {"radiosity", [](SolverProgress& p) { p.radiosity[1].r = -1.0; }},
      {"unshot power", [](SolverProgress& p) { p.unshotPowerW[0] = -0.5; }},
      {"shot counts", [](SolverProgress& p) { p.timesShot[0] = -3; }},
      {"energy ledger holds nan W", [](SolverProgress& p) { p.ledger.emitted = std::nan(""); }},
      {"energy ledger does not balance", [](SolverProgress& p) { p.ledger.unshot *= 2.0; }},
  };
  for (const auto& [says, edit] : edits) {
    SolverProgress edited = solver->progress();
    edit(edited);
    try {
      solver->restoreProgress(edited);
      ADD_FAILURE() << "accepted; expected: " << says;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(solver->history().size(), 3u);
  EXPECT_TRUE(std::isfinite(solver->ledger().emitted));
}

// A cells solve stopped after some rounds, saved and resumed in a new solver: bitwise the solve that
// never stopped (each cell's solver, the light waiting on portal patches by direction bin, the
// rounds); a resume with other cells' settings, or into one solve, is refused naming what differs.
// A cells solve stopped after 3 rounds, checkpointed to `path` and resumed, against the straight
// one (returned): the same rounds, iterations, ledger and radiosity, bit for bit.
std::unique_ptr<CellSolver> expectCellsResumeBitwise(const Scene& scene, const std::vector<Patch>& patches,
                                                     const CellPartition& partition, const SolveOptions& o,
                                                     const CellSolveSettings& settings, const std::string& path) {
  auto straight = std::make_unique<CellSolver>(scene, patches, partition, o, settings);
  while (!straight->done()) straight->round();
  EXPECT_GT(straight->rounds(), 4);
  size_t elementsAtTheStop = 0;
  {
    CellSolver stopped(scene, patches, partition, o, settings);
    for (int r = 0; r < 3; ++r) stopped.round();
    writeCellsCheckpoint(path, scene, stopped);
    elementsAtTheStop = stopped.elements().elements.size();
  }
  CellSolver resumed(scene, patches, partition, o, settings);
  resumeCellsFromCheckpoint(path, scene, resumed);
  EXPECT_EQ(resumed.rounds(), 3);
  while (!resumed.done()) resumed.round();
  EXPECT_EQ(resumed.rounds(), straight->rounds());
  EXPECT_EQ(resumed.iterations(), straight->iterations());
  const Ledger a = resumed.ledger(), b = straight->ledger();
  EXPECT_EQ(std::memcmp(&a, &b, sizeof(Ledger)), 0);
  EXPECT_TRUE(bitwiseEqual(resumed.radiosity(), straight->radiosity()));
  EXPECT_TRUE(bitwiseEqual(resumed.displayElementRadiosity(), straight->displayElementRadiosity()));
  EXPECT_EQ(resumed.elements().elements.size(), straight->elements().elements.size());
  if (o.subdivide == Subdivide::Adaptive) {
    EXPECT_GT(straight->elements().elements.size(), elementsAtTheStop) << "no split after the stop";
  }
  return straight;
}

TEST(Checkpoint, CellsResumeIsBitwiseTheStraightSolve) {
  TempDir dir;
  const auto path = (dir / "cells.ckpt").string();
  const Scene scene = loadScene("two-rooms");
  const std::vector<Patch> patches = meshScene(scene, 0.75);
  const CellPartition partition = findCells(scene, patches);
  SolveOptions o = test::optionsFor(Projection::Hemicube, 32);
  o.until = 1.0;
  o.untilUnshot = 0.02;
  o.formFactorCacheBytes = 16 << 20;
  const CellSolveSettings settings{0.75, 16, 4};
  const std::unique_ptr<CellSolver> straightSolve = expectCellsResumeBitwise(scene, patches, partition, o, settings, path);
  const CellSolver& straight = *straightSolve;

  auto refused = [&](const SolveOptions& options, const CellSolveSettings& cells, const std::string& says,
                     const CellPartition& cellsFound) {
    CellSolver other(scene, patches, cellsFound, options, cells);
    try {
      resumeCellsFromCheckpoint(path, scene, other);
      ADD_FAILURE() << "accepted; expected: " << says;
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
      EXPECT_EQ(other.rounds(), 0);
    }
  };
  refused(o, {0.75, 8, 4}, "--exchange-shots 16 there, 8 here", partition);
  refused(o, {0.75, 16, 0}, "--portal-bins 4 there, 0 here", partition);
  SolveOptions finer = o;
  finer.resolution = 64;
  refused(finer, settings, "--resolution 32 there, 64 here", partition);
  CellPartition merged = partition;  // the same patches, other cells
  merged.portals.clear();
  for (int& cell : merged.cellOfPatch) cell = 0;
  merged.cells.resize(1);
  refused(o, settings, "was written for other cells: " + std::to_string(straight.cellCount()) + " cells there, 1 here", merged);
  ProgressiveSolver one(scene, patches, o);
  try {
    resumeFromCheckpoint(path, one);
    ADD_FAILURE() << "a cells checkpoint resumed into one solve";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("is a checkpoint of a cells solve (--cells auto), not of one solve"),
              std::string::npos) << e.what();
  }
}

// Cells whose patches are cut into elements, uniform and adaptive (split before and after the stop,
// the portals' direction bins kept across a resume's new back end). To 10 % unshot: 14 rounds, the
// adaptive elements splitting in rounds 1 to 3 and 5, so that the resume at round 3 goes on through
// a split; to 2 % (34 rounds) the same checks took 2.5 times as long under ASan.
TEST(Checkpoint, CellsWithElementsResumeBitwise) {
  TempDir dir;
  const Scene scene = loadScene("two-rooms");
  const std::vector<Patch> patches = meshScene(scene, 0.75);
  const CellPartition partition = findCells(scene, patches);
  for (Subdivide subdivide : {Subdivide::Uniform, Subdivide::Adaptive}) {
    SCOPED_TRACE(toString(subdivide));
    SolveOptions o = test::optionsFor(Projection::Hemicube, 32);
    o.until = 1.0;
    o.untilUnshot = 0.1;
    o.subdivide = subdivide;
    o.minElementM = 0.2;
    const auto straight = expectCellsResumeBitwise(scene, patches, partition, o, {0.75, 16, 4},
                                                   (dir / "elements.ckpt").string());
    EXPECT_GT(straight->elements().elements.size(), patches.size());
  }
}

TEST(Checkpoint, MeshedSceneHashFollowsVerticesAndEmissionBitwise) {
  ScenePatches a = cornell();
  const std::uint64_t hash = meshedSceneHash(a.scene, a.patches);
  EXPECT_EQ(meshedSceneHash(a.scene, a.patches), hash);
  a.patches[7].vertices[2].x = std::nextafter(a.patches[7].vertices[2].x, 1e9);
  EXPECT_NE(meshedSceneHash(a.scene, a.patches), hash);
}

}  // namespace
}  // namespace radmesh
