#pragma once
// The JSON type of every glTF property radmesh reads, checked against glTF 2.0's schema before
// tinygltf reads the file: tinygltf replaces a property of the wrong type by its default without a
// word ("indices": "1" dropped the index buffer, "translation": ["a", 0, 0] the transform).
#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace radmesh {

// "node 3 'lamp'": the element's kind, its index in its array, and its name when it has one.
std::string gltfElementLabel(std::string_view kind, size_t index, const nlohmann::json& element);

// Throws SceneError naming the element and the property, e.g. node 0: `translation is ["a",0,0]
// (array), not 3 numbers`. A document that is no JSON object is left for tinygltf to refuse.
void checkGltfTypes(const std::string& path, const nlohmann::json& doc);

}  // namespace radmesh
