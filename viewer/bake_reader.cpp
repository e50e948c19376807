#include "viewer/bake_reader.h"

#include <tiny_gltf.h>

#include "solver/io/gltf_accessor.h"
#include "solver/io/gltf_load.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

std::optional<Bake> readBakeGlb(const std::string& path) {
  std::vector<std::string> warnings;
  const tinygltf::Model model = loadGltfModel(path, &warnings);
  if (model.meshes.size() != 1 || model.meshes[0].primitives.size() != 1) return std::nullopt;
  const tinygltf::Mesh& mesh = model.meshes[0];
  const tinygltf::Primitive& primitive = mesh.primitives[0];
  const auto attribute = [&](const char* name) {
    const auto it = primitive.attributes.find(name);
    return it == primitive.attributes.end() ? -1 : it->second;
  };
  if (attribute("COLOR_0") < 0 || !mesh.extras.Has("radiosityPerColorUnit")) return std::nullopt;
  if (attribute("POSITION") < 0 || attribute("NORMAL") < 0 || primitive.indices < 0)
    throw SceneError(path, "mesh 0 primitive 0", "is a bake without POSITION, NORMAL or indices",
                     "write the bake again with `radmesh solve SCENE --out FILE.glb`");
  const tinygltf::Value& unit = mesh.extras.Get("radiosityPerColorUnit");
  Bake bake;
  bake.radiosityPerColorUnit = unit.IsNumber() ? unit.GetNumberAsDouble() : 0.0;
  if (!(bake.radiosityPerColorUnit > 0.0))
    throw SceneError(path, "mesh 0 extras", "radiosityPerColorUnit is not a positive number",
                     "write the bake again with `radmesh solve SCENE --out FILE.glb`");

  bake.mesh.positions = readFloatVec3(model, attribute("POSITION"), path, "POSITION of the bake");
  bake.mesh.normals = readFloatVec3(model, attribute("NORMAL"), path, "NORMAL of the bake");
  const std::vector<Vec3> colours = readFloatVec3(model, attribute("COLOR_0"), path, "COLOR_0 of the bake");
  const std::vector<uint32_t> indices = readIndices(model, primitive.indices, path, "indices of the bake");
  const size_t n = bake.mesh.positions.size();
  if (bake.mesh.normals.size() != n || colours.size() != n || indices.size() % 3 != 0)
    throw SceneError(path, "mesh 0 primitive 0", "has attributes of different lengths or a partial triangle",
                     "write the bake again with `radmesh solve SCENE --out FILE.glb`");
  for (uint32_t i : indices)
    if (i >= n)
      throw SceneError(path, "indices of the bake", "index " + std::to_string(i) + " is past the " +
                                                        std::to_string(n) + " vertices",
                       "write the bake again with `radmesh solve SCENE --out FILE.glb`");
  bake.mesh.indices.assign(indices.begin(), indices.end());
  bake.mesh.patchOfTriangle.resize(indices.size() / 3);
  for (size_t t = 0; t < bake.mesh.patchOfTriangle.size(); ++t) bake.mesh.patchOfTriangle[t] = static_cast<int>(t);
  bake.vertexB.reserve(n);
  for (const Vec3& c : colours) bake.vertexB.push_back(c * bake.radiosityPerColorUnit);
  return bake;
}

SceneFrame bakeFrame(const Bake& bake) {
  const auto& p = bake.mesh.positions;
  const auto& idx = bake.mesh.indices;
  std::vector<FrameFace> faces;
  faces.reserve(idx.size() / 3);
  for (size_t t = 0; t + 2 < idx.size(); t += 3) {
    const Rgb sum = bake.vertexB[idx[t]] + bake.vertexB[idx[t + 1]] + bake.vertexB[idx[t + 2]];
    // COLOR_0 saturates at 1 in every channel: B at radiosityPerColorUnit or more.
    const bool saturated = glm::min(sum.r, glm::min(sum.g, sum.b)) >= 3.0 * bake.radiosityPerColorUnit * 0.999;
    faces.push_back({{p[idx[t]], p[idx[t + 1]], p[idx[t + 2]]}, saturated});
  }
  return frameOf(faces);
}

}  // namespace radmesh
