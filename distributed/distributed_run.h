#pragma once
// One process of a distributed run (`radmesh solve ... --distributed` under mpirun): MPI is
// started for `body` alone (mpi::Session), and an error on any process ends every process with a
// message naming its rank (mpi::abortRun): exit 2 for a scene or option error, 1 otherwise. Only
// process 0 prints on stdout (the others' progress would repeat it).
#include <functional>

#include "solver/radiosity/cell_ranks.h"

namespace radmesh::distributed {

void runDistributed(const std::function<void(CellRanks&)>& body);

}  // namespace radmesh::distributed
