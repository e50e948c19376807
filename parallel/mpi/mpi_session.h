#pragma once
// One process of a distributed run (`--distributed`, under mpirun). MPI errors return to the
// caller instead of aborting inside Open MPI, so that every failure is reported with the rank it
// happened on and the call that failed, and then ends every rank of the run.
#include <mpi.h>

#include <stdexcept>
#include <string>

namespace radmesh::mpi {

// A failed MPI call or a peer that went away: the message starts "rank R: ".
class MpiError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// MPI_Init_thread (funneled: only the thread that made the session calls MPI) on construction,
// MPI_Finalize on destruction. One per process; a second throws.
class Session {
 public:
  Session(int& argc, char**& argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0;
  int size_ = 1;
};

int worldRank();  // this process's rank in MPI_COMM_WORLD (0 before MPI_Init)

// Throws MpiError "rank R: CALL failed: <MPI's reason>" unless code is MPI_SUCCESS.
void check(int code, const char* call);

// Prints "radmesh: rank R: message" to stderr and ends every rank of the run with exitCode
// (MPI_Abort): one rank's error must not leave the others waiting for it forever.
[[noreturn]] void abortRun(const std::string& message, int exitCode);

}  // namespace radmesh::mpi
