#include "parallel/mpi/mpi_session.h"

#include <cstdio>

namespace radmesh::mpi {

Session::Session(int& argc, char**& argv) {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (initialized) throw MpiError("MPI is already initialized: one mpi::Session per process");
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

Session::~Session() { MPI_Finalize(); }

int worldRank() {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) return 0;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

void check(int code, const char* call) {
  if (code == MPI_SUCCESS) return;
  char reason[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, reason, &length);
  throw MpiError("rank " + std::to_string(worldRank()) + ": " + call + " failed: " +
                 std::string(reason, static_cast<std::size_t>(length)));
}

void abortRun(const std::string& message, int exitCode) {
  std::fprintf(stderr, "radmesh: rank %d: %s\n", worldRank(), message.c_str());
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, exitCode);
  std::abort();  // MPI_Abort does not return; this is for the compiler
}

}  // namespace radmesh::mpi
