#pragma once
// A command's scene: loaded with its repairs reported, or, under --strict, refused for them.
#include <string>
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh::cli {

// Loads pathOrName, with what the reader repaired (an unknown entity skipped, `rd 1` lowered...) in
// `warnings`. With `strict`, a scene that needed any repair is refused: SceneError listing them.
Scene loadCommandScene(const std::string& pathOrName, bool strict, std::vector<std::string>& warnings);

// The same for a command that only prints the warnings, on stderr.
Scene loadCommandScene(const std::string& pathOrName, bool strict);

}  // namespace radmesh::cli
