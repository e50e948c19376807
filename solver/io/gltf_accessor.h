#pragma once
// Reading glTF accessors with every offset and length checked against the buffers, so that a
// corrupt file gets a SceneError naming the accessor instead of a read past the end.
#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

// Errors name the accessor and what uses it: "accessor 3 (POSITION of mesh 'desk' primitive 0)";
// `use` is that second part.

// A float VEC3 accessor (POSITION), converted to doubles. NaN or infinite values are refused.
std::vector<Vec3> readFloatVec3(const tinygltf::Model& model, int index, const std::string& file,
                                const std::string& use);

// A colour accessor (COLOR_0): VEC3 or VEC4 (alpha dropped) of floats or of normalized unsigned
// bytes or shorts, as glTF 2.0 allows, in linear RGB.
std::vector<Rgb> readColours(const tinygltf::Model& model, int index, const std::string& file, const std::string& use);

// An unsigned-integer SCALAR accessor (u8, u16 or u32 indices).
std::vector<uint32_t> readIndices(const tinygltf::Model& model, int index, const std::string& file,
                                  const std::string& use);

}  // namespace radmesh
