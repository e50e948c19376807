#pragma once
// One entry point for every command that takes a SCENE: a built-in name or a .gltf/.glb/.mgf path.
#include <string>
#include <vector>

#include "solver/io/daylight.h"
#include "solver/scene/scene.h"

namespace radmesh {

inline constexpr const char* kDefaultScene = "office";

// Loads, lights by `daylight` (its sky at the openings, what that added a line each in `notes`; its
// sun among the scene's lights), and validates; throws SceneError with file, element and fix on
// anything unusable.
Scene loadScene(const std::string& pathOrName, std::vector<std::string>* warnings = nullptr,
                const Daylight& daylight = {}, std::vector<std::string>* notes = nullptr);

}  // namespace radmesh
