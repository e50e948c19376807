#pragma once
// What a checkpoint is of (its meshed scene, its options that change the answer) and the refusal of
// a resume into another solve, naming what differs; private to checkpoint.cpp.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "solver/radiosity/cell_solver.h"
#include "solver/radiosity/progressive_solver.h"
#include "solver/scene/scene.h"

namespace radmesh {

// Options as flag and value: compared as text, they name what differs.
using OptionList = std::vector<std::pair<std::string, std::string>>;

// What a checkpoint is of: resuming needs the same.
struct Identity {
  std::uint64_t sceneHash = 0;
  std::string sceneSource;
  std::uint64_t patches = 0;
  OptionList options;
};

Identity identityOf(const ProgressiveSolver& solver);

// The building's, with the settings that change a cells solve's answer.
Identity identityOf(const Scene& scene, const CellSolver& solver);

// Refuses (SceneError) a checkpoint at path of another meshed scene or of other options that change
// the answer; `now` is of a solve with `options`.
void checkSameSolve(const std::string& path, const Identity& was, const Identity& now, const SolveOptions& options);

}  // namespace radmesh
