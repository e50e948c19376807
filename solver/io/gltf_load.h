#pragma once
// Loading a .gltf or .glb file through tinygltf, with its failures turned into SceneErrors that
// name the element at fault (the JSON text, the GLB container, "buffer 0") and keep tinygltf's own
// message.
#include <tiny_gltf.h>

#include <string>
#include <vector>

namespace radmesh {

// Binary or text is told by the file's first bytes ("glTF" starts a .glb), not by its name.
// tinygltf's warnings are appended to `warnings`.
tinygltf::Model loadGltfModel(const std::string& path, std::vector<std::string>* warnings);

}  // namespace radmesh
