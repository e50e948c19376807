#include "solver/io/gltf_material.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>

#include "solver/scene/scene_error.h"

namespace radmesh {

namespace {

void warn(std::vector<std::string>* warnings, const std::string& file, const std::string& element,
          const std::string& message) {
  if (warnings) warnings->push_back(file + ": " + element + ": " + message);
}

// glTF colour textures are sRGB-encoded (glTF 2.0 spec, 3.9.2); radiosity needs linear values.
double srgbToLinear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// The mean linear RGB of an image's decoded texels (an average over texels, not over the texture
// as mapped onto the surface). Empty when the image was not decoded.
std::optional<Rgb> averageTexels(const tinygltf::Image& image) {
  const int bytesPerChannel = image.bits == 16 ? 2 : image.bits == 8 ? 1 : 0;
  if (bytesPerChannel == 0 || image.width <= 0 || image.height <= 0 || image.component <= 0) return std::nullopt;
  const size_t texels = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
  const size_t channels = static_cast<size_t>(image.component);
  if (image.image.size() < texels * channels * bytesPerChannel) return std::nullopt;
  const double maxValue = bytesPerChannel == 2 ? 65535.0 : 255.0;
  auto channel = [&](size_t texel, size_t c) {
    const size_t at = (texel * channels + std::min(c, channels - 1)) * bytesPerChannel;  // grey: one channel
    if (bytesPerChannel == 1) return image.image[at] / maxValue;
    uint16_t v;
    std::memcpy(&v, &image.image[at], sizeof v);
    return v / maxValue;
  };
  Rgb sum{0.0};
  for (size_t t = 0; t < texels; ++t)
    for (int c = 0; c < 3; ++c) sum[c] += srgbToLinear(channel(t, static_cast<size_t>(c)));
  return sum / static_cast<double>(texels);
}

// The average of a material's texture, 1 when it has none or it cannot be used.
Rgb textureAverage(const tinygltf::Model& model, const tinygltf::TextureInfo& info, const std::string& file,
                   const std::string& element, const std::string& slot, std::vector<std::string>* warnings) {
  if (info.index < 0) return Rgb(1.0);
  if (static_cast<size_t>(info.index) >= model.textures.size())
    throw SceneError(file, element, slot + " refers to texture " + std::to_string(info.index) + ", which does not exist",
                     "refer to an existing texture or remove the reference");
  const int source = model.textures[info.index].source;
  if (source < 0 || static_cast<size_t>(source) >= model.images.size()) {
    warn(warnings, file, element, slot + " has no image radmesh can read; using the factor alone");
    return Rgb(1.0);
  }
  // An image that could not be read or decoded was warned about once, when the file was loaded.
  return averageTexels(model.images[source]).value_or(Rgb(1.0));
}

std::string materialLabel(const tinygltf::Material& m, size_t index) {
  return "material " + std::to_string(index) + (m.name.empty() ? "" : " '" + m.name + "'");
}

Rgb reflectance(const tinygltf::Model& model, const tinygltf::Material& m, const std::string& file,
                const std::string& element, std::vector<std::string>* warnings) {
  const std::vector<double>& factor = m.pbrMetallicRoughness.baseColorFactor;  // 4 numbers: checkGltfTypes
  Rgb rho{factor[0], factor[1], factor[2]};
  for (int c = 0; c < 3; ++c)
    if (!(rho[c] >= 0.0 && rho[c] <= 1.0))
      throw SceneError(file, element, fmt::format("baseColorFactor {:g} is outside [0, 1]", rho[c]),
                       "give each baseColorFactor channel a value from 0 to 1");
  rho *= textureAverage(model, m.pbrMetallicRoughness.baseColorTexture, file, element, "baseColorTexture", warnings);
  if (rho.r > kHighestReflectance || rho.g > kHighestReflectance || rho.b > kHighestReflectance) {
    warn(warnings, file, element,
         fmt::format("reflectance above {:g} lowered to it (radiosity cannot converge with a reflectance of 1)",
                     kHighestReflectance));
    rho = glm::min(rho, Rgb(kHighestReflectance));
  }
  return rho;
}

Rgb emittance(const tinygltf::Model& model, const tinygltf::Material& m, const std::string& file,
              const std::string& element, std::vector<std::string>* warnings) {
  Rgb e{0.0};
  if (!m.emissiveFactor.empty()) {  // 3 numbers: checkGltfTypes
    e = Rgb(m.emissiveFactor[0], m.emissiveFactor[1], m.emissiveFactor[2]);
    for (int c = 0; c < 3; ++c)
      requireNonNegativeFactor(e[c], "emissiveFactor", file, element, "give emissiveFactor 3 numbers >= 0 (linear RGB)");
    // Beyond glTF's [0, 1], but three.js and the Khronos sample viewer light with it as given.
    if (e.r > 1.0 || e.g > 1.0 || e.b > 1.0)
      warn(warnings, file, element,
           fmt::format("emissiveFactor ({}, {}, {}) is above glTF's 1, read as given (fix: give emissiveFactor at "
                       "most 1, and the rest as KHR_materials_emissive_strength)",
                       e.r, e.g, e.b));
  }
  double strength = 1.0;
  const auto ext = m.extensions.find("KHR_materials_emissive_strength");
  if (ext != m.extensions.end() && ext->second.Has("emissiveStrength")) {
    strength = ext->second.Get("emissiveStrength").GetNumberAsDouble();  // a number: checkGltfTypes
    requireNonNegativeFactor(strength, "KHR_materials_emissive_strength.emissiveStrength", file, element,
                             "give emissiveStrength a number >= 0 (W/m^2 per unit emissiveFactor)");
  }
  e *= strength;  // a product that overflows is refused with the scene (validateScene)
  if (e == Rgb(0.0)) return e;  // no need to decode an emissive texture of a dark material
  return e * textureAverage(model, m.emissiveTexture, file, element, "emissiveTexture", warnings);
}

}  // namespace

Material defaultGltfMaterial() { return Material{"default (grey)", Rgb(0.5), Rgb(0.0)}; }

std::vector<Material> convertGltfMaterials(const tinygltf::Model& model, const std::string& file,
                                           std::vector<std::string>* warnings) {
  std::vector<Material> out;
  out.reserve(model.materials.size());
  for (size_t i = 0; i < model.materials.size(); ++i) {
    const tinygltf::Material& m = model.materials[i];
    const std::string element = materialLabel(m, i);
    Material converted;
    converted.name = m.name.empty() ? "material " + std::to_string(i) : m.name;
    converted.rho = reflectance(model, m, file, element, warnings);
    converted.emittance = emittance(model, m, file, element, warnings);
    out.push_back(converted);
  }
  return out;
}

}  // namespace radmesh
