#include "solver/io/gltf_document.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <string_view>

#include "solver/io/file_signature.h"
#include "solver/io/gltf_types.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

namespace {

namespace fs = std::filesystem;

constexpr size_t kGlbHeaderBytes = 20;  // magic, version, length, then the JSON chunk's length and type

// tinygltf's JSON parser (and nlohmann's, used here) recurse once per level of nesting: 20000 '['
// overflow the stack. Real files nest a few dozen levels at most.
constexpr int kMaxJsonDepth = 512;

uint32_t littleEndian32(const std::string& bytes, size_t at) {
  uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(bytes[at + k]);
  return v;
}

// The document's KHR_lights_punctual lights (an empty array when it has none).
nlohmann::json lightsOf(const nlohmann::json& doc) {
  if (doc.is_object() && doc.contains("extensions") && doc["extensions"].is_object() &&
      doc["extensions"].contains("KHR_lights_punctual") && doc["extensions"]["KHR_lights_punctual"].is_object())
    return doc["extensions"]["KHR_lights_punctual"].value("lights", nlohmann::json::array());
  return nlohmann::json::array();
}

// Whether the JSON text nests arrays and objects deeper than `limit`, counting brackets outside strings.
bool nestsDeeperThan(std::string_view json, int limit) {
  int depth = 0;
  bool inString = false;
  for (size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (inString) {
      if (c == '\\') ++i;  // an escaped character, '"' included
      else if (c == '"') inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) return true;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return false;
}

// glTF 1.0 (a different format: its materials are shaders, its buffers typed) loaded as if it were
// 2.0. The GLB header's version and asset.version's major number must both say 2.
void checkVersion(const std::string& path, const std::string& bytes, const nlohmann::json& doc) {
  const std::string fix = "re-export the model as glTF 2.0";
  if (isGlb(bytes) && bytes.size() >= 8)
    if (const uint32_t glb = littleEndian32(bytes, 4); glb != 2)
      throw SceneError(path, "GLB container",
                       fmt::format("its header says version {}, not 2: {}, which radmesh does not read", glb,
                                   glb == 1 ? "glTF 1.0's binary format"
                                            : "a GLB version that does not exist (2 is glTF 2.0's, 1 was glTF 1.0's)"),
                       fix);
  if (!doc.is_object() || !doc.contains("asset") || !doc["asset"].is_object() || !doc["asset"].contains("version") ||
      !doc["asset"]["version"].is_string())
    return;  // tinygltf refuses a missing version
  const std::string version = doc["asset"]["version"].get<std::string>();
  if (version.substr(0, version.find('.')) != "2")
    throw SceneError(path, "asset",
                     "its version is '" + version + "', not glTF 2.0" +
                         (version.starts_with("1.") ? " (glTF 1.0 is a different format)" : ""),
                     fix);
}

// What a file may list in extensionsRequired: the extensions radmesh reads, and those that change
// nothing it reads (it averages a texture's texels, so their placement does not matter; quantized
// positions are refused by name where they are read).
constexpr std::array<std::string_view, 5> kRequirableExtensions = {
    "KHR_lights_punctual", "KHR_materials_emissive_strength", "KHR_materials_unlit", "KHR_texture_transform",
    "KHR_mesh_quantization"};

// glTF 2.0 (3.12): a reader must refuse a file requiring an extension it does not implement.
// Unrefused, a compressed mesh loaded as nothing or failed as "no valid bufferView".
void checkRequiredExtensions(const std::string& path, const nlohmann::json& doc) {
  if (!doc.is_object() || !doc.contains("extensionsRequired") || !doc["extensionsRequired"].is_array()) return;
  for (const nlohmann::json& name : doc["extensionsRequired"]) {
    if (!name.is_string() || std::ranges::find(kRequirableExtensions, name.get<std::string>()) !=
                                 kRequirableExtensions.end())
      continue;
    const std::string extension = name.get<std::string>();
    throw SceneError(path, "extensionsRequired",
                     fmt::format("the file requires {}, which radmesh does not implement (it accepts {})", extension,
                                 fmt::join(kRequirableExtensions, ", ")),
                     extension.find("compression") != std::string::npos
                         ? "export the file without Draco or meshopt compression"
                         : "export the file without " + extension);
  }
}

// A URI's %XX escapes decoded, as tinygltf decodes them.
std::string percentDecoded(const std::string& uri) {
  std::string decoded;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      decoded += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      decoded += uri[i];
    }
  }
  return decoded;
}

// The file a buffer's or image's URI names: relative to the glTF file's folder (glTF 2.0 3.6.1).
fs::path uriFile(const std::string& path, const std::string& uri) {
  return fs::path(path).parent_path() / percentDecoded(uri);
}

// Calls f(what, index, entry, uri) for every buffer and image the document gives a URI.
template <class F> void forEachUri(const nlohmann::json& doc, F f) {
  for (const std::string array : {"buffers", "images"}) {
    if (!doc.is_object() || !doc.contains(array) || !doc[array].is_array()) continue;
    const std::string what = array == "buffers" ? "buffer" : "image";
    for (size_t i = 0; i < doc[array].size(); ++i) {
      const nlohmann::json& entry = doc[array][i];
      if (entry.is_object() && entry.contains("uri") && entry["uri"].is_string())
        f(what, i, entry, entry["uri"].get<std::string>());
    }
  }
}

// Every buffer and image the document names by a URI, not embedded, checked before tinygltf opens
// it: reading a FIFO would block for ever, a folder failed with std::bad_alloc, and a missing buffer
// would be looked for in the working directory too.
void checkExternalFiles(const std::string& path, const nlohmann::json& doc, std::vector<std::string>* warnings) {
  forEachUri(doc, [&](const std::string& what, size_t i, const nlohmann::json& entry, const std::string& uri) {
    const std::string element = what + " " + std::to_string(i);
    if (uri.rfind("data:", 0) == 0) {
      // tinygltf would look for a file of that name, and quote all of it.
      if (!tinygltf::IsDataURI(uri))
        throw SceneError(path, element,
                         fmt::format("its data: URI ('{}...') is not base64 of a type glTF embeds", uri.substr(0, 40)),
                         fmt::format("embed the {} as data:application/octet-stream;base64,... (or "
                                     "data:image/png;base64,... for a PNG)",
                                     what));
      return;
    }
    if (uri.find("://") != std::string::npos || fs::path(uri).has_root_path())
      throw SceneError(path, element,
                       "its uri '" + uri + "' is absolute; glTF names external files relative to the glTF file",
                       "copy the file beside the glTF file (or below it) and give its relative path");
    const fs::path file = uriFile(path, uri);
    const FileKind kind = fileKind(file);
    if (kind == FileKind::Folder || kind == FileKind::Special)
      throw SceneError(path, element,
                       fmt::format("its uri '{}' names '{}', which is {}, not a file", uri, file.string(),
                                   fileKindName(kind)),
                       fmt::format("give the uri of the {}'s file, beside the glTF file, or embed the {}", what, what));
    if (kind == FileKind::Missing && what == "buffer")
      throw SceneError(path, element, "its file '" + file.string() + "' does not exist",
                       "put '" + uri + "' beside the glTF file, or embed the buffer");
    if (kind == FileKind::Missing && warnings)  // an image: tinygltf's own two warnings are dropped
      warnings->push_back(path + ": " + element + ": its file '" + file.string() + "' does not exist: " +
                          kImageLeftOut);
    std::error_code ec;
    const uintmax_t size = fs::file_size(file, ec);
    if (what == "buffer" && !ec && entry.contains("byteLength") && entry["byteLength"].is_number_unsigned() &&
        size != entry["byteLength"].get<uint64_t>())
      throw SceneError(path, element,
                       fmt::format("its file '{}' has {} bytes, but its byteLength is {} (the buffer's length, "
                                   "which tinygltf requires the file to match)",
                                   file.string(), size, entry["byteLength"].get<uint64_t>()),
                       size < entry["byteLength"].get<uint64_t>()
                           ? "supply the whole buffer file (it may be truncated)"
                           : "set byteLength to the file's size, or export the file again");
  });
}

// The document's JSON: all of a .gltf, or the JSON chunk of a .glb that loaded.
std::string jsonOf(const std::string& bytes) {
  if (!isGlb(bytes) || bytes.size() < kGlbHeaderBytes) return bytes;
  return bytes.substr(kGlbHeaderBytes, std::min<size_t>(littleEndian32(bytes, 12), bytes.size() - kGlbHeaderBytes));
}

}  // namespace

std::map<std::string, std::string> plusUriFiles(const std::string& path, const nlohmann::json& doc) {
  std::map<std::string, std::string> files;
  const std::string folder = fs::path(path).parent_path().string();
  forEachUri(doc, [&](const std::string&, size_t, const nlohmann::json&, const std::string& uri) {
    if (uri.find('+') == std::string::npos || uri.starts_with("data:")) return;
    std::string spaced = uri;
    std::ranges::replace(spaced, '+', ' ');  // before the %XX escapes: "%2B" stays a '+'
    const std::string asked = percentDecoded(spaced);
    // Keyed as tinygltf joins its base folder and the name it decoded.
    files[folder.empty() || folder.ends_with('/') ? folder + asked : folder + "/" + asked] = uriFile(path, uri).string();
  });
  return files;
}

bool isGlb(const std::string& bytes) { return bytes.starts_with(kGlbSignature); }

nlohmann::json readGltfDocument(const std::string& path, const std::string& bytes, std::vector<std::string>* warnings) {
  if (nestsDeeperThan(jsonOf(bytes), kMaxJsonDepth))
    throw SceneError(path, "JSON",
                     fmt::format("nests arrays and objects more than {} levels deep, which no glTF needs (parsing it "
                                 "would overflow the stack)",
                                 kMaxJsonDepth),
                     "remove the deep nesting (look in \"extras\") or export the file again");
  nlohmann::json doc = nlohmann::json::parse(jsonOf(bytes), nullptr, /*allow_exceptions=*/false);
  // A document that is no JSON has neither: tinygltf says what is wrong with it.
  checkVersion(path, bytes, doc);
  checkRequiredExtensions(path, doc);
  checkGltfTypes(path, doc);  // before the URIs it checks are read
  checkExternalFiles(path, doc, warnings);
  return doc;
}

GltfDiagnosis diagnoseGltf(const std::string& bytes, const nlohmann::json& doc) {
  if (isGlb(bytes)) {
    const uint32_t declared = bytes.size() >= 12 ? littleEndian32(bytes, 8) : 0;
    const uint32_t jsonBytes = bytes.size() >= kGlbHeaderBytes ? littleEndian32(bytes, 12) : 0;
    const std::string damaged = "the file is truncated or damaged: export or copy it again";
    if (bytes.size() < kGlbHeaderBytes || declared > bytes.size())
      return {"GLB container",
              "the file has " + std::to_string(bytes.size()) + " bytes, its header declares " + std::to_string(declared),
              damaged};
    if (jsonBytes > bytes.size() - kGlbHeaderBytes)
      return {"GLB container",
              fmt::format("its JSON chunk declares {} bytes, but {} follow the chunk's header", jsonBytes,
                          bytes.size() - kGlbHeaderBytes),
              damaged};
  }
  if (doc.is_discarded())
    return {"JSON", "", "repair the JSON text (a truncated file ends mid-object)"};
  // tinygltf refuses a light without a type (or a spot without its cone) without naming it.
  const nlohmann::json lights = lightsOf(doc);
  for (size_t i = 0; lights.is_array() && i < lights.size(); ++i) {
    if (!lights[i].is_object()) continue;
    const std::string element = gltfElementLabel("KHR_lights_punctual light", i, lights[i]);
    if (!lights[i].contains("type") || !lights[i]["type"].is_string())
      return {element, "it has no type", "give it \"type\": \"point\", \"spot\" or \"directional\""};
    if (lights[i]["type"] == "spot" && !(lights[i].contains("spot") && lights[i]["spot"].is_object()))
      return {element, "a spot light without its \"spot\" object", "give it \"spot\": {\"outerConeAngle\": ...}"};
  }
  // tinygltf refuses an index buffer or an image's bufferView that names nothing without naming the
  // primitive or image. checkGltfTypes made both whole numbers.
  const auto outOfRange = [&](const nlohmann::json& user, const char* key, const char* array) -> std::string {
    const size_t count = doc.contains(array) ? doc[array].size() : 0;
    if (!user.contains(key) || user[key].get<uint64_t>() < count) return "";
    return fmt::format("{} {} names none of the file's {} {}", key, user[key].get<uint64_t>(), count, array);
  };
  const nlohmann::json none = nlohmann::json::array();
  const nlohmann::json meshes = doc.is_object() ? doc.value("meshes", none) : none;
  for (size_t m = 0; m < meshes.size(); ++m)
    for (size_t p = 0; p < meshes[m].value("primitives", none).size(); ++p)
      if (const std::string why = outOfRange(meshes[m]["primitives"][p], "indices", "accessors"); !why.empty())
        return {gltfElementLabel("mesh", m, meshes[m]) + " primitive " + std::to_string(p), why,
                "refer to an existing accessor (they count from 0)"};
  const nlohmann::json images = doc.is_object() ? doc.value("images", none) : none;
  for (size_t i = 0; i < images.size(); ++i)
    if (const std::string why = outOfRange(images[i], "bufferView", "bufferViews"); !why.empty())
      return {gltfElementLabel("image", i, images[i]), why, "refer to an existing bufferView (they count from 0)"};
  // radmesh uses no cameras, but tinygltf refuses a file with one it cannot read.
  const auto cameras = doc.find("cameras");
  for (size_t i = 0; cameras != doc.end() && cameras->is_array() && i < cameras->size(); ++i) {
    const nlohmann::json& camera = (*cameras)[i];
    const std::string type = camera.is_object() ? camera.value("type", std::string()) : std::string();
    if (type.empty() || !camera.contains(type) || !camera[type].is_object())
      return {"camera " + std::to_string(i), "it is incomplete (a \"" + type +
                                                "\" camera needs its \"" + type + "\" object; radmesh uses no cameras)",
              "give it its \"perspective\" or \"orthographic\" object, or delete the camera"};
  }
  const auto buffers = doc.find("buffers");
  if (buffers != doc.end() && buffers->is_array()) {
    for (size_t i = 0; i < buffers->size(); ++i) {
      const nlohmann::json& b = (*buffers)[i];
      if (!b.is_object() || !b.contains("uri") || !b["uri"].is_string()) continue;
      const std::string uri = b["uri"].get<std::string>();
      const std::string element = "buffer " + std::to_string(i);
      const bool declared = b.contains("byteLength") && b["byteLength"].is_number_unsigned();
      if (uri.rfind("data:", 0) == 0) {
        // Base64 carries 3 bytes in 4 characters, less its '=' padding.
        const size_t comma = uri.find(',');
        if (comma == std::string::npos || !declared) continue;
        const std::string_view payload = std::string_view(uri).substr(comma + 1);
        const size_t padding = payload.size() - std::min(payload.size(), payload.find_last_not_of('=') + 1);
        const uint64_t held = payload.size() / 4 * 3 - std::min<uint64_t>(padding, payload.size() / 4 * 3);
        if (held < b["byteLength"].get<uint64_t>())
          return {element, fmt::format("its data: URI holds {} bytes, fewer than its byteLength, {}", held,
                                       b["byteLength"].get<uint64_t>()),
                  "export the file again (the embedded buffer and its byteLength disagree)"};
        continue;
      }
    }
  }
  return {"", "", "check that the file is valid glTF 2.0 (for example with the Khronos glTF validator)"};
}

}  // namespace radmesh
