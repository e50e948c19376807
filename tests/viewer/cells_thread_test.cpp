// The viewer's cells solve: the camera's room is solved first, and the focus follows the eye.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "solver/cells/find_cells.h"
#include "solver/io/scene_loader.h"
#include "tests/viewer/solver_thread_wait.h"
#include "viewer/solver_thread.h"

namespace radmesh {
namespace {

using test::Snapshot;
using test::waitFor;

SolveSetup cellsSetup() {
  SolveSetup setup;
  setup.cells = true;
  setup.options.backend = Backend::Native;
  setup.options.resolution = 32;
  setup.options.until = 1.0;
  setup.options.untilUnshot = 0.0;  // only the steps stop it
  setup.options.threads = 1;
  return setup;
}

// 1.6 m above the middle of the named room's floor.
Vec3 eyeIn(const Scene& scene, const std::string& room) {
  for (const Polygon& polygon : scene.polygons) {
    if (groupOfOrigin(polygon.origin) != room || polygon.origin.find(" floor") == std::string::npos) continue;
    Vec3 middle(0.0);
    for (const Vec3& v : polygon.vertices) middle += v / double(polygon.vertices.size());
    return middle + Vec3(0.0, 0.0, 1.6);
  }
  ADD_FAILURE() << "no floor in " << room;
  return Vec3(0.0);
}

int cellNamed(const CellsProgress& cells, const std::string& name) {
  for (size_t c = 0; c < cells.cells.size(); ++c)
    if (cells.cells[c].name == name) return static_cast<int>(c);
  ADD_FAILURE() << "no cell " << name;
  return 0;
}

// With the eye in room r0c0 of building:3x3, the first round shoots 16 iterations there and none
// in the farthest room, which is left with more of its light unshot; walking into that room moves the
// focus there: the next round shoots it most.
TEST(CellsSolverThread, TheCamerasRoomIsSolvedFirstAndTheFocusFollowsTheEye) {
  const Scene scene = loadScene("building:3x3");
  SolverThread thread(scene, cellsSetup(), /*playing=*/false);
  thread.setEye(eyeIn(scene, "r0c0"));
  thread.step(1);
  const Snapshot first = waitFor(thread, [](const SolverSnapshot& s) { return s.cells && s.cells->rounds >= 1; });
  ASSERT_TRUE(first->cells);
  const CellsProgress& cells = *first->cells;
  EXPECT_EQ(cells.rounds, 1);
  const int room = cellNamed(cells, "r0c0");
  EXPECT_EQ(cells.focus, room);
  EXPECT_TRUE(cells.eyeInFocus);
  EXPECT_EQ(cells.cells[room].portalDistance, 0);
  EXPECT_EQ(cells.cells[room].iterations, 16);
  const auto far = std::max_element(cells.cells.begin(), cells.cells.end(), [](const auto& a, const auto& b) {
    return a.portalDistance < b.portalDistance;
  });
  const int farCell = static_cast<int>(far - cells.cells.begin());
  ASSERT_GE(far->portalDistance, 4);
  EXPECT_EQ(far->iterations, 0) << "cells beyond the focus wait until it is below the stopping rule";
  EXPECT_LT(cells.cells[room].unshotFraction, far->unshotFraction);
  EXPECT_EQ(first->iteration(), [&] {
    int n = 0;
    for (const auto& c : cells.cells) n += c.iterations;
    return n;
  }());

  thread.setEye(eyeIn(scene, far->name));
  thread.step(1);
  const Snapshot second = waitFor(thread, [](const SolverSnapshot& s) { return s.cells && s.cells->rounds >= 2; });
  EXPECT_EQ(second->cells->focus, farCell);
  EXPECT_EQ(second->cells->cells[farCell].portalDistance, 0);
  // The second round shot the new focus more than any other cell.
  for (size_t c = 0; c < cells.cells.size(); ++c) {
    if (static_cast<int>(c) != farCell) {
      EXPECT_GT(second->cells->cells[farCell].iterations - cells.cells[farCell].iterations,
                second->cells->cells[c].iterations - cells.cells[c].iterations) << cells.cells[c].name;
    }
  }
}

// Before the eye is known, no cell is first: a round's budget (3 shots a cell) goes by unshot
// power, the lit room shooting most; outside every room, the nearest room is first.
TEST(CellsSolverThread, WithoutAnEyeShotsFollowTheUnshotPower) {
  const Scene scene = loadScene("building:1x1");
  SolveSetup setup = cellsSetup();
  setup.exchangeShots = 3;
  SolverThread thread(scene, setup, false);
  thread.step(1);
  const Snapshot s = waitFor(thread, [](const SolverSnapshot& s) { return s.cells && s.cells->rounds >= 1; });
  EXPECT_EQ(s->cells->focus, -1);
  int total = 0;
  for (const auto& c : s->cells->cells) {
    EXPECT_GE(c.iterations, 1) << c.name;
    EXPECT_LE(c.iterations, s->cells->cells[cellNamed(*s->cells, "r0c0")].iterations) << c.name;
    total += c.iterations;
  }
  EXPECT_LE(total, 3 * static_cast<int>(s->cells->cells.size()));
}

TEST(CellsSolverThread, AnEyeOutsideTheBuildingFocusesTheNearestRoom) {
  const Scene scene = loadScene("building:1x1");
  SolverThread thread(scene, cellsSetup(), false);
  thread.setEye(Vec3(-100.0, -100.0, 1.6));
  thread.step(1);
  const Snapshot s = waitFor(thread, [](const SolverSnapshot& s) { return s.cells && s.cells->rounds >= 1; });
  ASSERT_GE(s->cells->focus, 0);
  EXPECT_FALSE(s->cells->eyeInFocus);
  const CellPartition& partition = *s->cells->partition;
  for (size_t c = 0; c < partition.cells.size(); ++c) {
    const Vec3 eye(-100.0, -100.0, 1.6);
    auto distance = [&](const Cell& cell) { return glm::length(eye - glm::clamp(eye, cell.boundsMin, cell.boundsMax)); };
    EXPECT_LE(distance(partition.cells[s->cells->focus]), distance(partition.cells[c])) << partition.cells[c].name;
  }
}

// With elements the mesh is the cells' elements, each grouped in its patch's cell: uniform, every
// patch in four (listed patch by patch); adaptive, remeshed as the rooms' elements split.
TEST(CellsSolverThread, DrawsTheCellsElements) {
  const Scene scene = loadScene("building:1x1");
  for (Subdivide how : {Subdivide::Uniform, Subdivide::Adaptive}) {
    SolveSetup setup = cellsSetup();
    setup.cellM = 0.75;
    setup.exchangeShots = 4;
    setup.options.subdivide = how;
    setup.options.minElementM = how == Subdivide::Adaptive ? 0.2 : 0.0;
    SolverThread thread(scene, setup, false);
    thread.step(1);
    const Snapshot s = waitFor(thread, [](const SolverSnapshot& s) { return s.cells && s.cells->rounds >= 1; });
    const std::vector<int>& cellOf = *s->cells->cellOfReceiver;
    const std::vector<int>& cellOfPatch = s->cells->partition->cellOfPatch;
    ASSERT_EQ(*std::max_element(s->mesh->patchOfTriangle.begin(), s->mesh->patchOfTriangle.end()) + 1,
              static_cast<int>(cellOf.size())) << toString(how);
    EXPECT_EQ(s->vertexB.size(), s->mesh->positions.size());
    if (how == Subdivide::Uniform) {
      ASSERT_EQ(cellOf.size(), 4 * cellOfPatch.size());
      for (size_t e = 0; e < cellOf.size(); ++e) ASSERT_EQ(cellOf[e], cellOfPatch[e / 4]) << "element " << e;
    } else {
      EXPECT_GT(cellOf.size(), cellOfPatch.size()) << "elements split in the first round";
    }
  }
}

TEST(CellsSolverThread, ACellsSolveOnTheMeshBackEndIsRefusedWithTheFix) {
  SolveSetup setup = cellsSetup();
  setup.options.backend = Backend::Mesh;
  SolverThread thread(loadScene("building:1x1"), setup, false);
  const Snapshot s = waitFor(thread, [](const SolverSnapshot& s) { return !s.error.empty(); });
  EXPECT_NE(s->error.find("--backend native"), std::string::npos) << s->error;
  EXPECT_TRUE(s->errorIsInput);  // the user's to fix: the viewer exits 2, as radmesh solve
}

// A resumed cells solve shows where it stood from its first snapshot: 16 iterations in round 1 of
// building:1x1 (it said 0 until the next round), that point of the curve, and the camera's room as
// its focus (none until the next round, when the run was made before the window had an eye).
TEST(CellsSolverThread, AResumedCellsSolveShowsTheRestoredIterations) {
  const auto dir = std::filesystem::temp_directory_path() / ("radmesh-cells-resume-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "cells.ckpt").string();
  const Scene scene = loadScene("building:1x1");
  SolveSetup setup = cellsSetup();
  setup.cellM = 0.75;
  SolverThread first(scene, setup, false);
  first.step(1);
  const Snapshot saved = waitFor(first, [](const SolverSnapshot& s) { return s.cells && s.cells->rounds >= 1; });
  first.saveCheckpoint(path);
  waitFor(first, [](const SolverSnapshot& s) { return s.checkpointMessage.starts_with("saved"); });

  SolverThread reopened(scene, setup, false, path, 0, eyeIn(scene, "r0c0"));
  const Snapshot resumed = waitFor(reopened, [](const SolverSnapshot& s) { return s.mesh || !s.error.empty(); });
  ASSERT_EQ(resumed->error, "");
  EXPECT_EQ(resumed->cells->rounds, 1);
  EXPECT_EQ(resumed->cells->focus, cellNamed(*resumed->cells, "r0c0"));
  EXPECT_TRUE(resumed->cells->eyeInFocus);
  EXPECT_EQ(resumed->iteration(), saved->iteration());
  EXPECT_GT(resumed->iteration(), 0);
  ASSERT_EQ(resumed->curve.size(), 1u);
  EXPECT_EQ(resumed->curve.back().unshotFraction, saved->curve.back().unshotFraction);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace radmesh
