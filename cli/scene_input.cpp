#include "cli/scene_input.h"

#include <fmt/core.h>

#include "solver/io/scene_loader.h"
#include "solver/scene/scene_error.h"

namespace radmesh::cli {

Scene loadCommandScene(const std::string& pathOrName, bool strict, const Daylight& daylight,
                       std::vector<std::string>& warnings, std::vector<std::string>& notes) {
  Scene scene = loadScene(pathOrName, &warnings, daylight, &notes);
  if (strict && !warnings.empty()) {
    std::string list;
    for (const std::string& w : warnings) list += "\n  " + w;
    throw SceneError(pathOrName, "--strict",
                     fmt::format("needed {} kind(s) of repair, each an error under --strict:{}", warnings.size(), list),
                     "fix the file, or drop --strict to open it repaired");
  }
  return scene;
}

Scene loadCommandScene(const std::string& pathOrName, bool strict, const Daylight& daylight) {
  std::vector<std::string> warnings, notes;
  Scene scene = loadCommandScene(pathOrName, strict, daylight, warnings, notes);
  for (const std::string& w : warnings) fmt::print(stderr, "radmesh: warning: {}\n", w);
  for (const std::string& n : notes) fmt::print("{}\n", n);
  return scene;
}

}  // namespace radmesh::cli
