#pragma once
// One entry point for every command that takes a SCENE: a built-in name or a .gltf/.glb/.mgf path.
#include <string>
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

inline constexpr const char* kDefaultScene = "office";

// Loads and validates, with `addedLights` (--sun) among the scene's own, so that a scene they
// alone light is accepted; throws SceneError with file, element and fix on anything unusable.
Scene loadScene(const std::string& pathOrName, std::vector<std::string>* warnings = nullptr,
                const std::vector<Light>& addedLights = {});

}  // namespace radmesh
