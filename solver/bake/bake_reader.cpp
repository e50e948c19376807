#include "solver/bake/bake_reader.h"

#include <tiny_gltf.h>

#include <cmath>

#include "solver/io/gltf_accessor.h"
#include "solver/io/gltf_import.h"
#include "solver/io/gltf_load.h"
#include "solver/io/scene_loader.h"
#include "solver/scene/scene_error.h"
#include "solver/scene/up_axis.h"

namespace radmesh {

namespace {

constexpr const char* kWriteAgain = "write the bake again with `radmesh solve SCENE --out FILE.glb`";

int axisNamed(const tinygltf::Value& value) {
  const std::string name = value.IsString() ? value.Get<std::string>() : "";
  return name == "x" ? 0 : name == "y" ? 1 : name == "z" ? 2 : -1;
}

// Another tool's bake: its triangles with their COLOR_0 as radiosity (W/m^2 at 1), flat normals.
std::optional<Bake> readOtherToolsBake(const tinygltf::Model& model, const std::string& path) {
  GltfColouredTriangles read = readGltfColouredTriangles(model, path);
  if (read.colours.empty() || read.emits) return std::nullopt;  // a scene to solve
  Bake bake;
  bake.fromRadmesh = false;
  for (size_t t = 0; t < read.triangles.size(); ++t) {
    const std::vector<Vec3>& v = read.triangles[t].vertices;
    const Vec3 normal = newellNormal(v);
    for (int k = 0; k < 3; ++k) {
      bake.mesh.indices.push_back(static_cast<unsigned>(bake.mesh.positions.size()));
      bake.mesh.positions.push_back(v[k]);
      bake.mesh.normals.push_back(glm::length(normal) > 0.0 ? glm::normalize(normal) : Vec3(0, 1, 0));
      bake.vertexB.push_back(glm::max(read.colours[t][k], Rgb(0.0)));
    }
    bake.mesh.patchOfTriangle.push_back(static_cast<int>(t));
  }
  return bake;
}

}  // namespace

std::optional<Bake> readBake(const std::string& path) {
  const std::string extension = lowerCaseExtension(path);
  if (extension != ".gltf" && extension != ".glb") return std::nullopt;
  checkSceneFile(path);
  std::vector<std::string> warnings;
  const tinygltf::Model model = loadGltfModel(path, &warnings);
  const bool radmesh = model.meshes.size() == 1 && model.meshes[0].primitives.size() == 1 &&
                       model.meshes[0].primitives[0].attributes.count("COLOR_0") > 0 &&
                       model.meshes[0].extras.Has("radiosityPerColorUnit");
  if (!radmesh) return readOtherToolsBake(model, path);
  const tinygltf::Mesh& mesh = model.meshes[0];
  const tinygltf::Primitive& primitive = mesh.primitives[0];
  const auto attribute = [&](const char* name) {
    const auto it = primitive.attributes.find(name);
    return it == primitive.attributes.end() ? -1 : it->second;
  };
  if (attribute("POSITION") < 0 || attribute("NORMAL") < 0 || primitive.indices < 0)
    throw SceneError(path, "mesh 0 primitive 0", "is a bake without POSITION, NORMAL or indices", kWriteAgain);
  const tinygltf::Value& unit = mesh.extras.Get("radiosityPerColorUnit");
  Bake bake;
  bake.radiosityPerColorUnit = unit.IsNumber() ? unit.GetNumberAsDouble() : 0.0;
  if (!(bake.radiosityPerColorUnit > 0.0))
    throw SceneError(path, "mesh 0 extras", "radiosityPerColorUnit is not a positive number", kWriteAgain);
  if (mesh.extras.Has("sourceUp")) {
    bake.sourceUp = axisNamed(mesh.extras.Get("sourceUp"));
    if (bake.sourceUp < 0) throw SceneError(path, "mesh 0 extras", "sourceUp is not \"x\", \"y\" or \"z\"", kWriteAgain);
  }

  bake.mesh.positions = readFloatVec3(model, attribute("POSITION"), path, "POSITION of the bake");
  // A model far from the origin is written about its centre, its node translated back (gltf_export.h).
  for (const tinygltf::Node& node : model.nodes)
    if (node.mesh == 0 && node.translation.size() == 3)
      for (Vec3& p : bake.mesh.positions) p += Vec3(node.translation[0], node.translation[1], node.translation[2]);
  bake.mesh.normals = readFloatVec3(model, attribute("NORMAL"), path, "NORMAL of the bake");
  const std::vector<Vec3> colours = readFloatVec3(model, attribute("COLOR_0"), path, "COLOR_0 of the bake");
  const std::vector<uint32_t> indices = readIndices(model, primitive.indices, path, "indices of the bake");
  const size_t n = bake.mesh.positions.size();
  if (bake.mesh.normals.size() != n || colours.size() != n || indices.size() % 3 != 0)
    throw SceneError(path, "mesh 0 primitive 0", "has attributes of different lengths or a partial triangle",
                     kWriteAgain);
  for (uint32_t i : indices)
    if (i >= n)
      throw SceneError(path, "indices of the bake",
                       "index " + std::to_string(i) + " is past the " + std::to_string(n) + " vertices", kWriteAgain);
  bake.mesh.indices.assign(indices.begin(), indices.end());
  bake.mesh.patchOfTriangle.resize(indices.size() / 3);
  for (size_t t = 0; t < bake.mesh.patchOfTriangle.size(); ++t) bake.mesh.patchOfTriangle[t] = static_cast<int>(t);
  if (attribute("_RADIOSITY") >= 0) {  // B unclipped; a bake written before it has COLOR_0 alone
    bake.vertexB = readFloatVec3(model, attribute("_RADIOSITY"), path, "_RADIOSITY of the bake");
    if (bake.vertexB.size() != n)
      throw SceneError(path, "mesh 0 primitive 0", "has attributes of different lengths", kWriteAgain);
    for (const Rgb& b : bake.vertexB)
      if (!(b.r >= 0.0 && b.g >= 0.0 && b.b >= 0.0 && std::isfinite(b.r + b.g + b.b)))
        throw SceneError(path, "_RADIOSITY of the bake", "holds a radiosity that is negative or not finite",
                         kWriteAgain);
  } else {
    bake.vertexB.reserve(n);
    for (const Vec3& c : colours) bake.vertexB.push_back(c * bake.radiosityPerColorUnit);
  }
  if (bake.sourceUp < 0) bake.upAxis = guessUpAxis(bakeScene(bake, path));  // written before bakes were turned y-up
  return bake;
}

Scene bakeScene(const Bake& bake, const std::string& path) {
  Scene scene;
  scene.source = path;
  scene.upAxis = bake.upAxis;
  scene.materials = {{"bake", Rgb(0.5), Rgb(0.0)}, {"bake, saturated", Rgb(0.0), Rgb(1.0)}};
  const auto& p = bake.mesh.positions;
  const auto& idx = bake.mesh.indices;
  scene.polygons.reserve(idx.size() / 3);
  for (size_t t = 0; t + 2 < idx.size(); t += 3) {
    const Rgb sum = bake.vertexB[idx[t]] + bake.vertexB[idx[t + 1]] + bake.vertexB[idx[t + 2]];
    // COLOR_0 saturates at 1 in every channel: B at radiosityPerColorUnit or more.
    const bool saturated = glm::min(sum.r, glm::min(sum.g, sum.b)) >= 3.0 * bake.radiosityPerColorUnit * 0.999;
    scene.polygons.push_back({{p[idx[t]], p[idx[t + 1]], p[idx[t + 2]]}, saturated ? 1 : 0, "triangle " + std::to_string(t / 3)});
  }
  return scene;
}

}  // namespace radmesh
