#include "distributed/distributed_run.h"

#include <cstdio>
#include <exception>
#include <string>

#include "distributed/mpi_cell_ranks.h"
#include "parallel/mpi/mpi_session.h"
#include "solver/scene/scene_error.h"

namespace radmesh::distributed {

void runDistributed(const std::function<void(CellRanks&)>& body) {
  int argc = 0;
  char** argv = nullptr;
  mpi::Session session(argc, argv);
  try {
    if (session.rank() != 0 && !std::freopen("/dev/null", "w", stdout))
      throw std::runtime_error("cannot silence stdout on /dev/null");
    MpiCellRanks ranks;
    body(ranks);
    std::fflush(stdout);
  } catch (const SceneError& e) {
    mpi::abortRun(std::string("error: ") + e.what(), 2);
  } catch (const OptionError& e) {
    mpi::abortRun(std::string("error: ") + e.what(), 2);
  } catch (const std::exception& e) {
    // abortRun names the rank: an MPI error's own "rank N: " would say it twice.
    std::string what = e.what();
    if (const std::string rank = "rank " + std::to_string(session.rank()) + ": "; what.starts_with(rank))
      what.erase(0, rank.size());
    mpi::abortRun("error: " + what, 1);
  }
}

}  // namespace radmesh::distributed
