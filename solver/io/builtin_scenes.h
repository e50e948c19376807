#pragma once
// The built-in scenes: office (the default), cornell, furnace, two-rooms.
#include <string>
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

const std::vector<std::string>& builtinSceneNames();
bool isBuiltinScene(const std::string& name);
Scene builtinScene(const std::string& name);  // throws SceneError for an unknown name

}  // namespace radmesh
