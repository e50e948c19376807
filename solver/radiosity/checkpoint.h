#pragma once
// Checkpoints of a solve (docs/checkpoints.md): the solver's progress, the options that change
// its answer and a hash of its meshed scene, in one binary file that names its format, its
// version and its size and ends in no surprise (a checksum over the payload). Resuming from one
// goes on bitwise as if the solve had never stopped.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "solver/meshing/patch.h"
#include "solver/radiosity/cell_solver.h"
#include "solver/radiosity/progressive_solver.h"
#include "solver/scene/scene.h"

namespace radmesh {

// 2: the ledger keeps lightOutside; 3: elements (--subdivide), portal patches and cells solves;
// 4: the ledger keeps lightOnBackFaces.
inline constexpr std::uint32_t kCheckpointVersion = 4;

// Why a checkpoint could not be written: what() names the file, the reason and the command line's
// fix (--checkpoint); reason() is the reason alone, for the viewer's panel to give its own fix.
class CheckpointWriteError : public std::runtime_error {
 public:
  CheckpointWriteError(const std::string& path, const std::string& reason);
  const std::string& reason() const { return reason_; }

 private:
  std::string reason_;
};

// Writes the solver's state to path atomically: a temporary file in the same folder, flushed to
// disk, then renamed over path, so that a kill at any moment leaves the last good checkpoint.
// Throws CheckpointWriteError when it cannot.
void writeCheckpoint(const std::string& path, const ProgressiveSolver& solver);

// Throws as writeCheckpoint would when path's folder cannot take a file: to know before solving.
void checkCheckpointWritable(const std::string& path);

// Whether a file that is not a checkpoint is at `path` (a scene's included file, a document): a
// checkpoint has no extension of its own to check, so what is there is, before it is replaced.
bool holdsSomethingElse(const std::string& path);

// Puts the state saved in path into a solver just made of the same meshed scene and the same
// options that change the answer. Throws SceneError naming the file, what differs and the fix for
// a checkpoint of another scene or other options, or a truncated or corrupted one; the solver is
// then untouched.
void resumeFromCheckpoint(const std::string& path, ProgressiveSolver& solver);

// A cells solve's checkpoint (--cells auto): the building's identity and options with the cells'
// settings, its cells, the rounds so far, the lights' ledger and each cell's solver as
// writeCheckpoint saves one solve. In a distributed solve every process calls it: process 0
// gathers every cell's state and alone writes the one file (atomically, as writeCheckpoint).
void writeCellsCheckpoint(const std::string& path, const Scene& scene, const CellSolver& solver);

// Puts the state saved in path into a cells solver just made of the same scene and options, on
// any number of processes (each takes its own cells; every process calls it). Throws SceneError
// naming the file, what differs (the scene, an option, the cells) and the fix; then the solver is
// untouched, except for a cell state corrupted past its checksum, after which it is to be dropped.
void resumeCellsFromCheckpoint(const std::string& path, const Scene& scene, CellSolver& solver);

// FNV-1a 64 over the patches' vertices, their materials' reflectance and emission, and the lights, bitwise.
std::uint64_t meshedSceneHash(const Scene& scene, const std::vector<Patch>& patches);

}  // namespace radmesh
