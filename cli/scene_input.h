#pragma once
// A command's scene: loaded with its repairs reported, or, under --strict, refused for them.
#include <string>
#include <vector>

#include "solver/io/daylight.h"
#include "solver/scene/scene.h"

namespace radmesh::cli {

// Loads pathOrName, with what the reader repaired (an unknown entity skipped, `rd 1` lowered...) in
// `warnings`, lit by `daylight` (--sky, --sun) (what that added in `notes`). With `strict`, a scene
// that needed any repair is refused: SceneError listing them.
Scene loadCommandScene(const std::string& pathOrName, bool strict, const Daylight& daylight,
                       std::vector<std::string>& warnings, std::vector<std::string>& notes);

// The same for a command that only prints them: the warnings on stderr, the notes on stdout.
Scene loadCommandScene(const std::string& pathOrName, bool strict, const Daylight& daylight = {});

}  // namespace radmesh::cli
