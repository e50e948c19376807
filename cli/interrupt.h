#pragma once
// Ctrl-C during a long solve: the solve stops at the end of the iteration (or round) under way, so
// that its checkpoint can still be written, and a second Ctrl-C ends the program at once.
#include <exception>
#include <string>

namespace radmesh::cli {

// From now on, SIGINT and SIGTERM ask the solve loops to stop (interrupted()); a second one
// ends the program as the signal would.
void stopSolvesOnInterrupt();

// Whether a stop was asked for since stopSolvesOnInterrupt.
bool interrupted();

// Thrown once the interrupted solve's work is saved (or said to be lost): main exits 130, as a
// shell reports a program ended by Ctrl-C.
struct Interrupted : std::exception {
  const char* what() const noexcept override { return "interrupted"; }
};

// After Ctrl-C, says on stderr where the solve stopped (`where`: "iteration 12") and what holds its
// work: the checkpoint written at `checkpointPath`, or nothing (`keepHint` says how to keep it);
// then throws Interrupted. Nothing else is written: a bake, stats or picture of a solve cut short
// would pass for a finished one.
[[noreturn]] void stopAfterInterrupt(const std::string& where, const std::string& checkpointPath,
                                     const std::string& keepHint);

}  // namespace radmesh::cli
