#pragma once
// glTF 2.0 (.gltf / .glb) import through tinygltf.
#include <string>

#include "solver/scene.h"

namespace radmesh {

// Reads triangles of every mesh node (with node transforms), materials as rho = baseColorFactor
// (x texture average) and E = emissiveFactor x KHR_materials_emissive_strength, and merges coplanar
// adjacent triangles of one material into polygons. Throws SceneError on bad input.
Scene importGltf(const std::string& path, std::vector<std::string>* warnings = nullptr);

}  // namespace radmesh
