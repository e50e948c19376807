#include "distributed/distributed_run.h"

#include <chrono>
#include <cstdio>
#include <exception>
#include <string>
#include <thread>

#include "distributed/mpi_cell_ranks.h"
#include "parallel/mpi/mpi_session.h"
#include "solver/scene/scene_error.h"

namespace radmesh::distributed {

namespace {

// A scene or option error is every process's alike: rank 0 says it and its abort ends the others,
// which wait a moment first (sixteen copies of one message, mixed with the launcher's, said it
// before). One that only another rank meets is still said, a moment late.
[[noreturn]] void abortOnUsageError(int rank, const std::string& what) {
  if (rank != 0) std::this_thread::sleep_for(std::chrono::seconds(2));
  mpi::abortRun("error: " + what, 2);
}

}  // namespace

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
    abortOnUsageError(session.rank(), e.what());
  } catch (const OptionError& e) {
    abortOnUsageError(session.rank(), e.what());
  } catch (const std::exception& e) {
    // abortRun names the rank: an MPI error's own "rank N: " would say it twice.
    std::string what = e.what();
    if (const std::string rank = "rank " + std::to_string(session.rank()) + ": "; what.starts_with(rank))
      what.erase(0, rank.size());
    mpi::abortRun("error: " + what, 1);
  }
}

}  // namespace radmesh::distributed
