#pragma once
// A command's scene: loaded with its repairs reported, or, under --strict, refused for them.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "solver/bake/bake_reader.h"
#include "solver/scene/up_axis.h"

namespace radmesh::cli {

// Loads pathOrName, with what the reader repaired (an unknown entity skipped, `rd 1` lowered...) in
// `warnings`. With `strict`, a scene that needed any repair is refused: SceneError listing them.
// `up` sets its up axis (--up); what --up auto chose is printed on stderr.
Scene loadCommandScene(const std::string& pathOrName, bool strict, UpChoice up, std::vector<std::string>& warnings);

// The same for a command that only prints the warnings, on stderr.
Scene loadCommandScene(const std::string& pathOrName, bool strict, UpChoice up);

// The bake at `path` with its up axis set by `up`, or empty when `path` is not a glTF bake
// (solver/bake/bake_reader.h).
std::optional<Bake> readCommandBake(const std::string& path, UpChoice up);

// Adds --up to a subcommand.
void addUpOption(CLI::App* cmd, UpChoice& up);

}  // namespace radmesh::cli
