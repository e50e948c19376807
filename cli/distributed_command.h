#pragma once
// `--distributed` (solve, bench solve): every process of the mpirun runs `body` with its part of the
// run, the one place a command's distributed run starts.
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>

#include "solver/radiosity/cell_ranks.h"

namespace radmesh {
class ProgressiveSolver;
namespace emu {
class Transport;
}
}  // namespace radmesh

namespace radmesh::cli {

// This process's part of a distributed run: process 0 alone writes.
struct Processes {
  CellRanks& ranks;  // the cells solve's; and which process this is
  // --backend mesh without --cells: the PE machine split over the processes, and the stats'
  // "distributed" of the solve (collective: every process asks).
  std::shared_ptr<emu::Transport> meshMachine;
  std::function<nlohmann::json(const ProgressiveSolver&)> meshStats;
};

// Under an MPI launcher (mpirun -np N, Open MPI's or MPICH's), how many processes run this command
// and which one this is, from the environment the launcher sets; {1, 0} outside one.
struct Launch {
  int processes = 1;
  int rank = 0;
};
Launch mpiLaunch();

// With cellsOn each process solves some cells; else, with meshBackend, each holds a block of the
// PE machine. Refused, naming the fix, with neither or in a build without MPI.
void runDistributed(bool cellsOn, bool meshBackend, const std::function<void(Processes&)>& body);

}  // namespace radmesh::cli
