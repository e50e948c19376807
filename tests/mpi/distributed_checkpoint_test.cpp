// A distributed cells solve's checkpoint (solver/radiosity/checkpoint.h): process 0 gathers every
// process's cells into one file; resumed on the run's processes, or in one process, the solve goes
// on bit for bit as the solve that never stopped.
#include <gtest/gtest.h>
#include <mpi.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "distributed/mpi_cell_ranks.h"
#include "solver/cells/find_cells.h"
#include "solver/io/builtin_scenes.h"
#include "solver/meshing/meshing.h"
#include "solver/radiosity/checkpoint.h"

namespace radmesh {
namespace {

SolveOptions fastOptions() {
  SolveOptions o;
  o.projection = Projection::Hemicube;
  o.resolution = 32;
  o.until = 1.0;
  o.untilUnshot = 0.02;
  o.threads = 1;
  return o;
}

// One path on every process: rank 0's pid names the folder.
std::string sharedPath(const std::string& name) {
  int pid = static_cast<int>(getpid());
  MPI_Bcast(&pid, 1, MPI_INT, 0, MPI_COMM_WORLD);
  const auto dir = std::filesystem::temp_directory_path() / ("radmesh-mpi-checkpoint-" + std::to_string(pid));
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

TEST(DistributedCheckpoint, ResumedOnTheRunsProcessesOrInOneEqualsTheStraightSolve) {
  const Scene scene = builtinScene("two-rooms");
  const std::vector<Patch> patches = meshScene(scene, 0.75);
  const CellPartition partition = findCells(scene, patches);
  const CellSolveSettings settings{0.75, 16, 4};
  CellSolver straight(scene, patches, partition, fastOptions(), settings);
  while (!straight.done()) straight.round();
  ASSERT_GT(straight.rounds(), 4);

  distributed::MpiCellRanks ranks;
  const std::string path = sharedPath("cells.ckpt");
  {
    CellSolver stopped(scene, patches, partition, fastOptions(), settings, &ranks);
    for (int r = 0; r < 3; ++r) stopped.round();
    writeCellsCheckpoint(path, scene, stopped);
  }
  MPI_Barrier(MPI_COMM_WORLD);  // written on process 0 before any reads it
  CellSolver resumed(scene, patches, partition, fastOptions(), settings, &ranks);
  resumeCellsFromCheckpoint(path, scene, resumed);
  EXPECT_EQ(resumed.rounds(), 3);
  while (!resumed.done()) resumed.round();
  CellSolver alone(scene, patches, partition, fastOptions(), settings);  // the same file, one process
  resumeCellsFromCheckpoint(path, scene, alone);
  while (!alone.done()) alone.round();

  for (const CellSolver* solver : {&resumed, &alone}) {
    EXPECT_EQ(solver->rounds(), straight.rounds());
    EXPECT_EQ(solver->iterations(), straight.iterations());
    const Ledger a = solver->ledger(), b = straight.ledger();
    EXPECT_EQ(a.absorbed, b.absorbed);
    EXPECT_EQ(a.unshot, b.unshot);
    EXPECT_EQ(a.emitted, b.emitted);
    EXPECT_TRUE(solver->radiosity() == straight.radiosity());
  }
  MPI_Barrier(MPI_COMM_WORLD);
  if (ranks.rank() == 0) std::filesystem::remove_all(std::filesystem::path(path).parent_path());
}

}  // namespace
}  // namespace radmesh
