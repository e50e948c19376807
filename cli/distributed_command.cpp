#include "cli/distributed_command.h"

#include "solver/scene/scene_error.h"
#ifdef RADMESH_HAVE_MPI
#include "distributed/distributed_run.h"
#endif

namespace radmesh::cli {

void runDistributedCells(bool cellsOn, const std::function<void(CellRanks&)>& body) {
  if (!cellsOn)
    throw OptionError("--distributed splits a cells solve over processes: give --cells auto (the mesh machine over "
                      "MPI, --backend mesh --distributed, is not in this build yet)");
#ifdef RADMESH_HAVE_MPI
  distributed::runDistributed(body);
#else
  throw OptionError("--distributed: this radmesh was built without MPI; install libopenmpi-dev and openmpi-bin "
                    "(scripts/install-deps.sh), build again, and run it under mpirun");
#endif
}

}  // namespace radmesh::cli
