#include "solver/bake/gltf_export.h"

#include <fmt/format.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "solver/scene/scene_error.h"
#include "solver/scene/up_axis.h"

namespace radmesh {

namespace {

constexpr double kExposurePercentile = 0.9;

void checkInput(const DisplayMesh& mesh, const std::vector<Rgb>& radiosity) {
  const size_t n = mesh.positions.size();
  if (n == 0) throw std::invalid_argument("writeBakeGlb: the display mesh has no vertices");
  if (mesh.normals.size() != n || radiosity.size() != n)
    throw std::invalid_argument("writeBakeGlb: " + std::to_string(n) + " positions but " +
                                std::to_string(mesh.normals.size()) + " normals and " +
                                std::to_string(radiosity.size()) + " radiosities");
  if (mesh.indices.empty() || mesh.indices.size() % 3 != 0)
    throw std::invalid_argument("writeBakeGlb: index count " + std::to_string(mesh.indices.size()) +
                                " is not a positive multiple of 3");
  for (unsigned i : mesh.indices)
    if (i >= n) throw std::invalid_argument("writeBakeGlb: index " + std::to_string(i) + " out of range");
  for (const Rgb& b : radiosity)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(b[c]) || b[c] < 0.0)
        throw std::invalid_argument("writeBakeGlb: a vertex radiosity is negative or not finite; not written");
      else if (b[c] > std::numeric_limits<float>::max())  // the bake would hold inf, which no reader takes
        throw std::runtime_error(fmt::format("a vertex radiosity of {:.3g} W/m^2 is beyond what a bake's 32-bit "
                                             "floats hold ({:.3g}): the bake is not written; give the lights "
                                             "their physical power",
                                             b[c], std::numeric_limits<float>::max()));
}

template <class T>
size_t append(std::vector<unsigned char>& bytes, const std::vector<T>& values) {
  const size_t offset = bytes.size();  // every section is 4-byte sized, so stays aligned
  bytes.resize(offset + values.size() * sizeof(T));
  std::memcpy(bytes.data() + offset, values.data(), values.size() * sizeof(T));
  return offset;
}

int addAccessor(tinygltf::Model& model, size_t offset, size_t bytes, int target, int componentType, int type,
                size_t count) {
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = offset;
  view.byteLength = bytes;
  view.target = target;
  model.bufferViews.push_back(view);
  tinygltf::Accessor accessor;
  accessor.bufferView = static_cast<int>(model.bufferViews.size()) - 1;
  accessor.componentType = componentType;
  accessor.type = type;
  accessor.count = count;
  model.accessors.push_back(accessor);
  return static_cast<int>(model.accessors.size()) - 1;
}

std::vector<float> flatten(const std::vector<Vec3>& v) {
  std::vector<float> out;
  out.reserve(3 * v.size());
  for (const Vec3& p : v)
    for (int c = 0; c < 3; ++c) out.push_back(static_cast<float>(p[c]));
  return out;
}

tinygltf::Material unlitMaterial() {
  tinygltf::Material m;
  m.name = "radiosity (unlit vertex colour)";
  m.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, 1.0};
  m.pbrMetallicRoughness.metallicFactor = 0.0;
  m.pbrMetallicRoughness.roughnessFactor = 1.0;
  m.emissiveFactor = {0.0, 0.0, 0.0};
  m.extensions["KHR_materials_unlit"] = tinygltf::Value(tinygltf::Value::Object{});
  return m;
}

}  // namespace

double bakeRadiosityPerColorUnit(const std::vector<Rgb>& vertexRadiosity) {
  if (vertexRadiosity.empty()) return 1.0;
  std::vector<double> peak;
  peak.reserve(vertexRadiosity.size());
  for (const Rgb& b : vertexRadiosity) peak.push_back(std::max({b.r, b.g, b.b}));
  const double maximum = *std::max_element(peak.begin(), peak.end());
  const auto at = peak.begin() + static_cast<std::ptrdiff_t>(kExposurePercentile * (peak.size() - 1));
  std::nth_element(peak.begin(), at, peak.end());
  if (*at > 0.0) return *at;
  return maximum > 0.0 ? maximum : 1.0;
}

void writeBakeGlb(const std::string& path, const DisplayMesh& mesh, const std::vector<Rgb>& vertexRadiosity,
                  int sceneUpAxis) {
  checkInput(mesh, vertexRadiosity);
  const size_t n = mesh.positions.size();
  const double perUnit = bakeRadiosityPerColorUnit(vertexRadiosity);
  std::vector<Vec3> positions(n), normals(n), colors(n), radiosity(n);
  for (size_t i = 0; i < n; ++i) {
    positions[i] = rotateToYUp(mesh.positions[i], sceneUpAxis);
    const double length = glm::length(mesh.normals[i]);
    normals[i] = length > 0.0 ? rotateToYUp(mesh.normals[i] / length, sceneUpAxis) : Vec3(0, 1, 0);  // glTF wants unit normals
    colors[i] = glm::min(vertexRadiosity[i] / perUnit, Rgb(1.0));
    radiosity[i] = vertexRadiosity[i];
  }
  // Positions are floats: a model far from the origin (1e7 m) would snap to whole metres. Such a
  // model is written about its centre, the offset kept in double as its node's translation.
  const BoundingBox box = boundingBox(positions);
  const Vec3 centre = positions.empty() ? Vec3(0.0) : 0.5 * (box.low + box.high);
  const bool offset = glm::length(centre) > 8.0 * glm::length(box.high - box.low);
  if (offset)
    for (Vec3& p : positions) p -= centre;
  const std::vector<float> positionData = flatten(positions);

  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "radmesh";
  tinygltf::Buffer buffer;
  const size_t positionAt = append(buffer.data, positionData);
  const size_t normalAt = append(buffer.data, flatten(normals));
  const size_t colorAt = append(buffer.data, flatten(colors));
  const size_t radiosityAt = append(buffer.data, flatten(radiosity));
  const size_t indexAt = append(buffer.data, std::vector<uint32_t>(mesh.indices.begin(), mesh.indices.end()));
  const size_t vec3Bytes = 3 * sizeof(float) * n;
  model.buffers.push_back(std::move(buffer));

  tinygltf::Primitive prim;
  prim.mode = TINYGLTF_MODE_TRIANGLES;
  prim.material = 0;
  prim.attributes["POSITION"] = addAccessor(model, positionAt, vec3Bytes, TINYGLTF_TARGET_ARRAY_BUFFER,
                                            TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
  tinygltf::Accessor& position = model.accessors.back();
  position.minValues = {positionData[0], positionData[1], positionData[2]};  // glTF requires POSITION bounds
  position.maxValues = position.minValues;
  for (size_t i = 0; i < positionData.size(); ++i) {
    position.minValues[i % 3] = std::min<double>(position.minValues[i % 3], positionData[i]);
    position.maxValues[i % 3] = std::max<double>(position.maxValues[i % 3], positionData[i]);
  }
  prim.attributes["NORMAL"] = addAccessor(model, normalAt, vec3Bytes, TINYGLTF_TARGET_ARRAY_BUFFER,
                                          TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
  prim.attributes["COLOR_0"] = addAccessor(model, colorAt, vec3Bytes, TINYGLTF_TARGET_ARRAY_BUFFER,
                                           TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
  // B itself, unclipped: COLOR_0 saturates the lights and whatever is brighter than its unit, and
  // radmesh reads a bake back as the scene it drew (an application's attribute starts with _).
  prim.attributes["_RADIOSITY"] = addAccessor(model, radiosityAt, vec3Bytes, TINYGLTF_TARGET_ARRAY_BUFFER,
                                              TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
  prim.indices = addAccessor(model, indexAt, sizeof(uint32_t) * mesh.indices.size(),
                             TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                             TINYGLTF_TYPE_SCALAR, mesh.indices.size());

  tinygltf::Mesh bake;
  bake.name = "radiosity bake";
  bake.primitives.push_back(prim);
  bake.extras = tinygltf::Value(tinygltf::Value::Object{
      {"radiosityPerColorUnit", tinygltf::Value(perUnit)},
      {"sourceUp", tinygltf::Value(std::string(upAxisName(sceneUpAxis)))},
      {"note", tinygltf::Value(std::string("COLOR_0 = min(1, B / radiosityPerColorUnit), B in W/m^2, _RADIOSITY = B; "
                                           "the scene's sourceUp axis turned onto glTF's +y (docs/scene-formats.md)"))}});
  model.meshes.push_back(bake);
  model.materials.push_back(unlitMaterial());
  model.extensionsUsed.push_back("KHR_materials_unlit");
  tinygltf::Node node;
  node.mesh = 0;
  if (offset) node.translation = {centre.x, centre.y, centre.z};
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes = {0};
  model.scenes.push_back(scene);
  model.defaultScene = 0;

  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out)
    throw OptionError("cannot write the bake to '" + path + "': " + std::strerror(errno) +
                      " (fix: choose a file in an existing, writable directory)");
  tinygltf::TinyGLTF writer;
  const bool serialized = writer.WriteGltfSceneToStream(&model, out, /*prettyPrint=*/false, /*writeBinary=*/true);
  out.close();
  if (!serialized || !out)
    throw OptionError("writing the bake to '" + path + "' failed: " + std::strerror(errno) +
                      " (fix: check the free space and permissions of its directory)");
}

}  // namespace radmesh
