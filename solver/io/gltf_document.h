#pragma once
// A glTF file's JSON as radmesh reads it beside tinygltf: what tinygltf does not check (nesting that
// would overflow its parser, glTF 1.0, required extensions, properties' types, the files URIs name), and
// why tinygltf refused a file, which its own message seldom says.
#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <vector>

namespace radmesh {

// What becomes of an image that cannot be read: a texture only scales a material's colour.
inline constexpr const char* kImageLeftOut =
    "the textures using it are left out (their materials keep their factors alone)";

bool isGlb(const std::string& bytes);

// The document's JSON (all of a .gltf, the JSON chunk of a .glb), checked before tinygltf reads the
// file; discarded when it does not parse, for tinygltf to say why. Throws SceneError naming the
// element; a missing image is a warning.
nlohmann::json readGltfDocument(const std::string& path, const std::string& bytes, std::vector<std::string>* warnings);

// The files named by buffers' and images' URIs that hold a '+', by the path tinygltf asks for: it
// decodes a '+' as a space, as in a web form's query, where in a glTF URI (RFC 3986) it is a '+',
// as other glTF readers take it.
std::map<std::string, std::string> plusUriFiles(const std::string& path, const nlohmann::json& doc);

// Why tinygltf refused the file: the element at fault, a detail beside tinygltf's message, the fix.
struct GltfDiagnosis {
  std::string element;
  std::string detail;  // added to tinygltf's message
  std::string fix;
};

// Found by reading the file again ourselves: the GLB container, the JSON syntax, a light or camera
// tinygltf cannot read, or an embedded buffer that is short.
GltfDiagnosis diagnoseGltf(const std::string& bytes, const nlohmann::json& doc);

}  // namespace radmesh
