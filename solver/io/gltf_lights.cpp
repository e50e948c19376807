#include "solver/io/gltf_lights.h"

#include "solver/scene/scene_error.h"

namespace radmesh {

namespace {

LightType lightType(const std::string& type, const std::string& file, const std::string& element) {
  if (type == "point") return LightType::Point;
  if (type == "spot") return LightType::Spot;
  if (type == "directional") return LightType::Directional;
  throw SceneError(file, element, "has type '" + type + "', which KHR_lights_punctual does not define",
                   "use \"point\", \"spot\" or \"directional\"");
}

}  // namespace

int gltfNodeLight(const tinygltf::Node& node) {
  const auto extension = node.extensions.find("KHR_lights_punctual");
  if (extension == node.extensions.end() || !extension->second.Has("light")) return -1;
  const tinygltf::Value& light = extension->second.Get("light");
  return light.IsNumber() || light.IsInt() ? light.GetNumberAsInt() : -1;
}

Light gltfLight(const tinygltf::Model& model, int index, const glm::dmat4& world, const std::string& file,
                const std::string& node, int* rangeIgnored) {
  if (index < 0 || static_cast<size_t>(index) >= model.lights.size())
    throw SceneError(file, node, "refers to KHR_lights_punctual light " + std::to_string(index) + ", which does not exist",
                     "refer to an existing light");
  const tinygltf::Light& in = model.lights[index];
  const std::string element =
      "KHR_lights_punctual light " + std::to_string(index) + (in.name.empty() ? "" : " '" + in.name + "'") + " (" + node + ")";
  Light light;
  light.name = element;
  light.type = lightType(in.type, file, element);
  Rgb color(1.0);
  if (!in.color.empty()) color = Rgb(in.color[0], in.color[1], in.color[2]);  // 3 numbers: checkGltfTypes
  requireNonNegativeFactor(in.intensity, "intensity", file, element,
                           "give a finite intensity >= 0 (candela, or lux for a directional light)");
  for (int c = 0; c < 3; ++c)
    requireNonNegativeFactor(color[c], "color", file, element, "give color 3 linear RGB numbers >= 0");
  // A product that overflows is refused with the scene (validateScene).
  light.intensity = in.intensity * color / kWhiteEfficacyLmPerW;
  light.position = Vec3(world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
  const Vec3 along = Vec3(world * glm::dvec4(0.0, 0.0, -1.0, 0.0));  // the node's local -Z
  if (!(glm::length(along) > 0.0))
    throw SceneError(file, element, "points nowhere: its node's transform scales -Z to zero",
                     "give the node a non-zero scale");
  light.direction = glm::normalize(along);
  if (light.type == LightType::Spot) {
    light.innerConeRad = in.spot.innerConeAngle;
    light.outerConeRad = in.spot.outerConeAngle;
  }
  if (in.range > 0.0 && rangeIgnored) ++*rangeIgnored;
  return light;
}

}  // namespace radmesh
