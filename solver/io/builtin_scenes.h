#pragma once
// The built-in scenes: office (the default), cornell, furnace, two-rooms, and the generated
// building:COLSxROWS.
#include <string>
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

const std::vector<std::string>& builtinSceneNames();  // the fixed ones, not building:COLSxROWS
std::string builtinSceneForms();                       // every form, for messages: "office, ..., building:COLSxROWS"
bool isBuiltinScene(const std::string& name);          // true for any "building:..." (a bad size throws)
Scene builtinScene(const std::string& name);  // throws SceneError for an unknown name
// The file a scene given as `pathOrName` is read from: the path itself, a built-in's asset
// (cornell's glTF), or empty for a scene made in code.
std::string sceneFile(const std::string& pathOrName);

}  // namespace radmesh
