#pragma once
// `--distributed` (solve, bench solve): every process of the mpirun runs `body` with its part of the
// run. Refused, naming the fix, without --cells auto or in a build without MPI. The one place a
// command's distributed run starts: another back end over MPI (the mesh machine, --backend mesh)
// would be dispatched here, with its own transport beside CellRanks.
#include <functional>

#include "solver/radiosity/cell_ranks.h"

namespace radmesh::cli {

void runDistributedCells(bool cellsOn, const std::function<void(CellRanks&)>& body);

}  // namespace radmesh::cli
