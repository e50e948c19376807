#pragma once
// A command's scene: loaded with its repairs reported, or, under --strict, refused for them.
#include <string>
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh::cli {

// Loads pathOrName, with what the reader repaired (an unknown entity skipped, `rd 1` lowered...) in
// `warnings`. With `strict`, a scene that needed any repair is refused: SceneError listing them.
// `addedLights` (--sun) join the scene's own lights.
Scene loadCommandScene(const std::string& pathOrName, bool strict, std::vector<std::string>& warnings,
                       const std::vector<Light>& addedLights = {});

// The same for a command that only prints the warnings, on stderr.
Scene loadCommandScene(const std::string& pathOrName, bool strict, const std::vector<Light>& addedLights = {});

}  // namespace radmesh::cli
