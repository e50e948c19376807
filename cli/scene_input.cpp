#include "cli/scene_input.h"

#include <fmt/core.h>

#include "solver/io/scene_loader.h"
#include "solver/scene/scene_error.h"
#include "solver/scene/units.h"

namespace radmesh::cli {

Scene loadCommandScene(const std::string& pathOrName, bool strict, const Daylight& daylight, UpChoice up,
                       double metresPerUnit, std::vector<std::string>& warnings, std::vector<std::string>& notes) {
  std::vector<std::string> readNotes;
  Scene scene;
  try {
    scene = loadScene(pathOrName, &warnings, daylight, &notes, up, &readNotes, metresPerUnit);
  } catch (const SceneError&) {
    // What was repaired while reading may be why nothing is left (every face skipped).
    for (const std::string& w : warnings) fmt::print(stderr, "radmesh: warning: {}\n", w);
    throw;
  }
  for (const std::string& n : readNotes) fmt::print(stderr, "radmesh: {}\n", n);
  if (strict) refuseWarnings(pathOrName, warnings);
  return scene;
}

Scene loadCommandScene(const std::string& pathOrName, bool strict, const Daylight& daylight, UpChoice up,
                       double metresPerUnit) {
  std::vector<std::string> warnings, notes;
  Scene scene = loadCommandScene(pathOrName, strict, daylight, up, metresPerUnit, warnings, notes);
  for (const std::string& w : warnings) fmt::print(stderr, "radmesh: warning: {}\n", w);
  for (const std::string& n : notes) fmt::print("{}\n", n);
  return scene;
}

std::optional<Bake> readCommandBake(const std::string& path, UpChoice up, const std::vector<std::string>& given) {
  std::optional<Bake> bake = readBake(path);
  if (!bake) return std::nullopt;
  for (const std::string& flag : given)
    if (flag != "--up")  // the one scene flag a bake takes
      fmt::print(stderr, "radmesh: warning: {} does not apply: {} is a bake, already solved (it applies to scenes)\n",
                 flag, path);
  Scene geometry = bakeScene(*bake, path);
  const std::string chosen = applyUpChoice(geometry, up);
  if (!chosen.empty()) fmt::print(stderr, "radmesh: {}\n", chosen);
  bake->upAxis = geometry.upAxis;
  return bake;
}

void addUnitsOption(CLI::App* cmd, double& metresPerUnit) {
  cmd->add_option_function<std::string>(
      "--units", [&metresPerUnit](const std::string& v) { metresPerUnit = parseUnits(v); }, kUnitsHelp);
}

}  // namespace radmesh::cli
