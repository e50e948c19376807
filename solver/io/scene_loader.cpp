#include "solver/io/scene_loader.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

#include "solver/io/builtin_scenes.h"
#include "solver/io/gltf_import.h"
#include "solver/io/mgf_import.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

namespace {

std::string acceptedForms() {
  return "give a .gltf, .glb or .mgf file, or a built-in scene name (" + builtinSceneForms() + ")";
}

Scene importFile(const std::string& path, std::vector<std::string>* warnings) {
  std::error_code error;
  const std::filesystem::path p(path);
  if (!std::filesystem::exists(p, error))
    throw SceneError(path, "", "no such file, and not a built-in scene name", acceptedForms());
  if (std::filesystem::is_directory(p, error))
    throw SceneError(path, "", "is a directory, not a scene file", acceptedForms());
  std::string extension = p.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".gltf" || extension == ".glb") return importGltf(path, warnings);
  if (extension == ".mgf") return importMgf(path, warnings);
  throw SceneError(path, "",
                   "has an unknown extension '" + extension + "': radmesh reads glTF 2.0 and MGF scenes",
                   acceptedForms());
}

}  // namespace

Scene loadScene(const std::string& pathOrName, std::vector<std::string>* warnings, const Daylight& daylight,
                std::vector<std::string>* notes) {
  Scene scene = isBuiltinScene(pathOrName) ? builtinScene(pathOrName) : importFile(pathOrName, warnings);
  if (daylight.skyLux > 0.0) {
    validateGeometry(scene);  // openings are looked for in sound geometry only
    std::vector<std::string> added = addSkyEmitters(scene, daylight);
    if (notes) notes->insert(notes->end(), added.begin(), added.end());
  }
  scene.lights.insert(scene.lights.end(), daylight.sun.begin(), daylight.sun.end());
  validateScene(scene);
  return scene;
}

}  // namespace radmesh
