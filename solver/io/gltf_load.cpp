#include "solver/io/gltf_load.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>

#include "solver/io/file_signature.h"
#include "solver/io/gltf_document.h"
#include "solver/io/scene_loader.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

namespace {

namespace fs = std::filesystem;

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path, "", "cannot be opened", "check the path and the file's permissions");
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// tinygltf's message on one line, and short: it can quote a whole data: URI (megabytes of base64).
std::string oneLine(const std::string& message) {
  constexpr size_t kMaxChars = 400;
  std::string out;
  for (char c : message) {
    if (out.size() >= kMaxChars) {
      out += "...";
      break;
    }
    out += c == '\n' ? std::string("; ") : std::string(1, c);
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
  return out.empty() ? "no message" : out;
}

// A texture only scales a material's colour: one that cannot be decoded is warned about (the
// material keeps its factor alone) instead of refusing the whole scene.
bool decodeImageOrWarn(tinygltf::Image* image, const int index, std::string* /*err*/, std::string* warn, int width,
                       int height, const unsigned char* bytes, int size, void* options) {
  std::string why;
  if (tinygltf::LoadImageData(image, index, &why, warn, width, height, bytes, size, options)) return true;
  if (warn) *warn += "image " + std::to_string(index) + " could not be decoded (" + oneLine(why) + "): " + kImageLeftOut + "\n";
  return true;
}

// tinygltf's warnings but its two about a missing image file, which checkExternalFiles said in one.
void appendWarnings(const std::string& path, const std::string& text, std::vector<std::string>* warnings) {
  if (!warnings || text.empty()) return;
  size_t start = 0;
  while (start < text.size()) {
    const size_t end = std::min(text.find('\n', start), text.size());
    const std::string line = text.substr(start, end - start);
    if (!line.empty() && !line.starts_with("File not found : ") &&
        !line.starts_with("Failed to load external 'uri' for image["))
      warnings->push_back(path + ": " + line);
    start = end + 1;
  }
}

// tinygltf's file access, with the paths plusUriFiles lists (user data) read where their URIs point.
const std::string& fileFor(const std::string& asked, void* plusFiles) {
  const auto& files = *static_cast<const std::map<std::string, std::string>*>(plusFiles);
  const auto it = files.find(asked);
  return it == files.end() ? asked : it->second;
}
bool fileExists(const std::string& path, void* plusFiles) {
  return tinygltf::FileExists(fileFor(path, plusFiles), nullptr);
}
bool readWholeFile(std::vector<unsigned char>* out, std::string* error, const std::string& path, void* plusFiles) {
  return tinygltf::ReadWholeFile(out, error, fileFor(path, plusFiles), nullptr);
}

}  // namespace

tinygltf::Model loadGltfModel(const std::string& path, std::vector<std::string>* warnings) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw SceneError(path, "", "does not exist or is not a file", "check the path");
  const std::string bytes = readBytes(path);
  if (!isGlb(bytes) && lowerCaseExtension(path) == ".glb" && looksBinary(path))  // an image renamed, say
    throw SceneError(path, "GLB container", "is not a GLB: it does not start with 'glTF'",
                     "give a glTF binary (.glb) or a .gltf text file; check what the file really is");
  if (bytes.size() > std::numeric_limits<unsigned>::max())
    throw SceneError(path, "", "is larger than 4 GiB, more than tinygltf reads", "split the model");
  const nlohmann::json doc = readGltfDocument(path, bytes, warnings);
  const std::string baseDir = fs::path(path).parent_path().string();  // external buffers and images
  const auto length = static_cast<unsigned>(bytes.size());
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&decodeImageOrWarn, nullptr);  // no options: the decoder's defaults (RGBA)
  std::map<std::string, std::string> plusFiles = plusUriFiles(path, doc);
  loader.SetFsCallbacks({&fileExists, &tinygltf::ExpandFilePath, &readWholeFile, &tinygltf::WriteWholeFile, &plusFiles});
  tinygltf::Model model;
  std::string error, warning;
  bool loaded = false;
  try {
    loaded = isGlb(bytes)
                 ? loader.LoadBinaryFromMemory(&model, &error, &warning,
                                               reinterpret_cast<const unsigned char*>(bytes.data()), length, baseDir)
                 : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(), length, baseDir);
  } catch (const std::exception& e) {
    error += e.what();
  }
  appendWarnings(path, warning, warnings);
  // tinygltf may report an error yet return true (a bad optional part); trust only a clean load.
  if (loaded && error.empty()) return model;
  const GltfDiagnosis d = diagnoseGltf(bytes, doc);
  throw SceneError(path, d.element,
                   "could not be loaded (tinygltf: " + oneLine(error) + ")" +
                       (d.detail.empty() ? "" : ": " + d.detail),
                   d.fix);
}

}  // namespace radmesh
