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

// Loads pathOrName in `metresPerUnit` (--units; 0, not given: metres), with what the reader
// repaired (an unknown entity skipped, `rd 1` lowered...) in `warnings`, turned by `up` (--up; what
// --up auto chose is printed on stderr) and lit by `daylight` (--sky, --sun; what that added in
// `notes`). With `strict`, a scene that needed any repair is refused: SceneError listing them.
Scene loadCommandScene(const std::string& pathOrName, bool strict, const Daylight& daylight, UpChoice up,
                       double metresPerUnit, std::vector<std::string>& warnings, std::vector<std::string>& notes);

// The same for a command that only prints them: the warnings on stderr, the notes on stdout.
Scene loadCommandScene(const std::string& pathOrName, bool strict, const Daylight& daylight, UpChoice up,
                       double metresPerUnit);

// The bake at `path` with its up axis set by `up`, or empty when `path` is not a glTF bake
// (solver/bake/bake_reader.h). Each of the `given` scene flags but --up is warned of as not applying.
std::optional<Bake> readCommandBake(const std::string& path, UpChoice up, const std::vector<std::string>& given);

// Adds --up to a subcommand, or to radmesh-view (which compiles this header without the radmesh
// command's sources).
inline void addUpOption(CLI::App* cmd, UpChoice& up) {
  cmd->add_option_function<std::string>(
      "--up", [&up](const std::string& v) { up = parseUpChoice(v); },
      "Which axis is up: x, y, z, or auto (decided from the geometry); default: the format's (glTF y, the "
      "built-in rooms z; MGF, which does not say, auto)");
}
// Adds --units (metres per unit; 0 when not given).
void addUnitsOption(CLI::App* cmd, double& metresPerUnit);
inline constexpr const char* kUnitsHelp =
    "What the scene's coordinates are in: m, cm, mm, in or ft (default: metres, as glTF defines and MGF assumes)";
inline constexpr const char* kStrictHelp =
    "Refuse a scene that gave any warning as it was read (a repair, --units that make it implausibly sized): "
    "each warning an error";

}  // namespace radmesh::cli
