#pragma once
// What radmesh-view shows of a file: a scene to solve, or a bake to walk. The file named at launch,
// the panel's Open field and a file dropped on the window are all read here, the same way.
#include <optional>
#include <string>
#include <vector>

#include "solver/bake/bake_reader.h"
#include "solver/scene/scene.h"
#include "viewer/viewer_app.h"

namespace radmesh {

struct ViewedFile {
  std::string path;
  std::optional<Bake> bake;  // a bake is walked as it is
  Scene scene;               // the scene to solve, or the bake's geometry (it gives the camera's frame)
  SolveSetup setup;          // the launch's, with the cell chosen from this scene unless --cell was given
  std::vector<std::string> warnings;  // what the reader repaired, counted
  std::vector<std::string> notes;     // what it chose (the up axis, the cell) and why
};

// Throws SceneError naming the file (missing, truncated, not a scene; under --strict, one that needed
// repairs) and OptionError, changing nothing.
ViewedFile readViewedFile(const std::string& path, const ViewerArgs& args);

// "could not open PATH: why", the path said once: readViewedFile's errors mostly begin with it.
std::string openFailure(const std::string& path, const std::string& error);

}  // namespace radmesh
