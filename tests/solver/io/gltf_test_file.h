#pragma once
// Small glTF files written at test time: a builder for the JSON and its base64 buffer, and a
// temporary directory per test (so tests run in parallel without sharing files).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <string>
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh::test {

// A directory under the system's temp dir named after the running test; removed at the end.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("radmesh-" + std::string(info->test_suite_name()) + "-" + info->name() + "-" +
             std::to_string(::getpid()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

inline std::string base64(const std::vector<unsigned char>& bytes) {
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const uint32_t a = bytes[i], b = i + 1 < bytes.size() ? bytes[i + 1] : 0,
                   c = i + 2 < bytes.size() ? bytes[i + 2] : 0;
    const uint32_t triple = (a << 16) | (b << 8) | c;
    out += alphabet[(triple >> 18) & 63];
    out += alphabet[(triple >> 12) & 63];
    out += i + 1 < bytes.size() ? alphabet[(triple >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? alphabet[triple & 63] : '=';
  }
  return out;
}

// A glTF binary holding `json` as its only chunk, with the header's `version`.
inline std::string glbContainer(std::string json, uint32_t version = 2) {
  while (json.size() % 4) json += ' ';
  std::string glb;
  const auto word = [&](uint32_t v) {
    for (int k = 0; k < 4; ++k) glb += static_cast<char>(v >> (8 * k) & 0xFF);
  };
  glb += "glTF";
  word(version);
  word(static_cast<uint32_t>(20 + json.size()));
  word(static_cast<uint32_t>(json.size()));
  word(0x4E4F534Au);  // "JSON"
  return glb + json;
}

// Builds a glTF document; accessors go into one buffer, embedded as a data URI or written beside.
class GltfBuilder {
 public:
  GltfBuilder() { doc_ = {{"asset", {{"version", "2.0"}}}}; }

  nlohmann::json& doc() { return doc_; }

  int addPositions(const std::vector<Vec3>& points) {
    std::vector<float> f;
    for (const Vec3& p : points)
      for (int c = 0; c < 3; ++c) f.push_back(static_cast<float>(p[c]));
    return addAccessor(f.data(), f.size() * sizeof(float), 5126, "VEC3", points.size());
  }

  // componentType 5121 (u8), 5123 (u16) or 5125 (u32).
  int addIndices(const std::vector<uint32_t>& indices, int componentType = 5125) {
    std::vector<unsigned char> bytes;
    const size_t size = componentType == 5121 ? 1 : componentType == 5123 ? 2 : 4;
    for (uint32_t i : indices)
      for (size_t k = 0; k < size; ++k) bytes.push_back(static_cast<unsigned char>(i >> (8 * k)));
    return addAccessor(bytes.data(), bytes.size(), componentType, "SCALAR", indices.size());
  }

  int add(const std::string& array, nlohmann::json value) {
    doc_[array].push_back(std::move(value));
    return static_cast<int>(doc_[array].size()) - 1;
  }

  // A mesh of one primitive, and a node showing it; returns the node.
  int addTriangles(const std::string& name, int positions, int indices, int material,
                   nlohmann::json node = nlohmann::json::object()) {
    nlohmann::json prim = {{"attributes", {{"POSITION", positions}}}};
    if (indices >= 0) prim["indices"] = indices;
    if (material >= 0) prim["material"] = material;
    const int mesh = add("meshes", {{"name", name}, {"primitives", {prim}}});
    node["mesh"] = mesh;
    return add("nodes", node);
  }

  // Writes the .gltf with the buffer as a data URI (or as `binName` beside it), every node not
  // a child of another in scene 0 unless the document already has scenes.
  std::filesystem::path write(const std::filesystem::path& path, const std::string& binName = "") {
    nlohmann::json doc = doc_;
    if (!doc.contains("scenes") && doc.contains("nodes")) {
      std::vector<bool> child(doc["nodes"].size(), false);
      for (const auto& n : doc["nodes"])
        if (n.contains("children"))
          for (int c : n["children"]) child[c] = true;
      nlohmann::json roots = nlohmann::json::array();
      for (size_t i = 0; i < child.size(); ++i)
        if (!child[i]) roots.push_back(i);
      doc["scenes"] = {{{"nodes", roots}}};
      doc["scene"] = 0;
    }
    if (!bin_.empty()) {
      nlohmann::json buffer = {{"byteLength", bin_.size()}};
      if (binName.empty()) {
        buffer["uri"] = "data:application/octet-stream;base64," + base64(bin_);
      } else {
        buffer["uri"] = binName;
        std::ofstream(path.parent_path() / binName, std::ios::binary)
            .write(reinterpret_cast<const char*>(bin_.data()), static_cast<std::streamsize>(bin_.size()));
      }
      doc["buffers"] = {buffer};
    }
    std::ofstream(path) << doc.dump(1);
    return path;
  }

 private:
  int addAccessor(const void* data, size_t bytes, int componentType, const char* type, size_t count) {
    while (bin_.size() % 4) bin_.push_back(0);
    const size_t offset = bin_.size();
    bin_.resize(offset + bytes);
    std::memcpy(bin_.data() + offset, data, bytes);
    const int view = add("bufferViews", {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}});
    return add("accessors", {{"bufferView", view}, {"componentType", componentType}, {"type", type}, {"count", count}});
  }

  nlohmann::json doc_;
  std::vector<unsigned char> bin_;
};

}  // namespace radmesh::test
