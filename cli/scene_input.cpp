#include "cli/scene_input.h"

#include <fmt/core.h>

#include "solver/io/scene_loader.h"
#include "solver/scene/scene_error.h"

namespace radmesh::cli {

Scene loadCommandScene(const std::string& pathOrName, bool strict, UpChoice up, std::vector<std::string>& warnings) {
  std::string upNote;
  Scene scene = loadScene(pathOrName, &warnings, up, &upNote);
  if (!upNote.empty()) fmt::print(stderr, "radmesh: {}\n", upNote);
  if (strict && !warnings.empty()) {
    std::string list;
    for (const std::string& w : warnings) list += "\n  " + w;
    throw SceneError(pathOrName, "--strict",
                     fmt::format("needed {} kind(s) of repair, each an error under --strict:{}", warnings.size(), list),
                     "fix the file, or drop --strict to open it repaired");
  }
  return scene;
}

Scene loadCommandScene(const std::string& pathOrName, bool strict, UpChoice up) {
  std::vector<std::string> warnings;
  Scene scene = loadCommandScene(pathOrName, strict, up, warnings);
  for (const std::string& w : warnings) fmt::print(stderr, "radmesh: warning: {}\n", w);
  return scene;
}

std::optional<Bake> readCommandBake(const std::string& path, UpChoice up) {
  std::optional<Bake> bake = readBake(path);
  if (!bake) return std::nullopt;
  Scene geometry = bakeScene(*bake, path);
  const std::string chosen = applyUpChoice(geometry, up);
  if (!chosen.empty()) fmt::print(stderr, "radmesh: {}\n", chosen);
  bake->upAxis = geometry.upAxis;
  return bake;
}

void addUpOption(CLI::App* cmd, UpChoice& up) {
  cmd->add_option_function<std::string>(
      "--up", [&up](const std::string& v) { up = parseUpChoice(v); },
      "Which axis is up: x, y, z, or auto (decided from the geometry); default: the format's (MGF and the "
      "built-in rooms z, glTF y)");
}

}  // namespace radmesh::cli
