#pragma once
// A command's scene: loaded with its repairs reported, or, under --strict, refused for them.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "solver/io/daylight.h"
#include "solver/scene/scene.h"
#include "solver/bake/bake_reader.h"
#include "solver/scene/up_axis.h"

namespace radmesh::cli {

// Loads pathOrName, with what the reader repaired (an unknown entity skipped, `rd 1` lowered...) in
// `warnings`, turned by `up` (--up; what --up auto chose is printed on stderr) and lit by `daylight`
// (--sky, --sun; what that added in `notes`). With `strict`, a scene that needed any repair is
// refused: SceneError listing them.
Scene loadCommandScene(const std::string& pathOrName, bool strict, const Daylight& daylight, UpChoice up,
                       std::vector<std::string>& warnings, std::vector<std::string>& notes);

// The same for a command that only prints them: the warnings on stderr, the notes on stdout.
Scene loadCommandScene(const std::string& pathOrName, bool strict, const Daylight& daylight, UpChoice up);

// The bake at `path` with its up axis set by `up`, or empty when `path` is not a glTF bake
// (solver/bake/bake_reader.h).
std::optional<Bake> readCommandBake(const std::string& path, UpChoice up);

// Adds --up to a subcommand.
void addUpOption(CLI::App* cmd, UpChoice& up);

}  // namespace radmesh::cli
