#pragma once
// glTF materials as radiosity materials: rho = baseColorFactor.rgb x the average of the
// baseColorTexture, E = emissiveFactor x KHR_materials_emissive_strength x the average of the
// emissiveTexture (W/m^2, radiant exitance).
#include <tiny_gltf.h>

#include <string>
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

// The grey used for primitives without a material.
Material defaultGltfMaterial();

// One Material per model.materials entry, in order. Unnamed materials are called "material N".
// Throws SceneError for factors outside glTF's ranges, negative emission or broken texture
// references; warns (textures that cannot be decoded, a reflectance of 1 lowered) and goes on.
std::vector<Material> convertGltfMaterials(const tinygltf::Model& model, const std::string& file,
                                           std::vector<std::string>* warnings);

}  // namespace radmesh
