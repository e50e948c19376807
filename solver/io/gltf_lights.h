#pragma once
// KHR_lights_punctual: the point, spot and directional lights a glTF file places on its nodes.
#include <string>

#include <glm/glm.hpp>

#include "solver/io/gltf_load.h"
#include "solver/scene/scene.h"

namespace radmesh {

// Light `index` of the file's KHR_lights_punctual lights as placed by a node's world transform:
// at its origin, shining along its local -Z. Photometric to radiometric (docs/scene-formats.md):
// each channel is intensity x color / kWhiteEfficacyLmPerW (179 lm/W, as MGF's `ed` and IES
// luminaires), candela becoming W/sr (point, spot) and lux W/m^2 (directional). `range` is not
// applied (the inverse square holds all the way): *rangeIgnored counts the lights that had one.
// Throws SceneError naming the light and its node for an index out of range, an unknown type, a
// colour that is not 3 numbers, or a negative, NaN or infinite intensity or colour.
Light gltfLight(const tinygltf::Model& model, int index, const glm::dmat4& world, const std::string& file,
                const std::string& node, int* rangeIgnored);

// The light index a node's KHR_lights_punctual extension names, or -1 for none.
int gltfNodeLight(const tinygltf::Node& node);

}  // namespace radmesh
