#include "solver/io/scene_loader.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include <fmt/format.h>

#include "solver/io/builtin_scenes.h"
#include "solver/io/file_signature.h"
#include "solver/io/gltf_import.h"
#include "solver/io/mgf_import.h"
#include "solver/scene/doubled_polygons.h"
#include "solver/scene/scene_error.h"
#include "solver/scene/units.h"

namespace radmesh {

namespace {

std::string acceptedForms() {
  return "give a .gltf, .glb or .mgf file, or a built-in scene name (" + builtinSceneForms() + ")";
}

Scene importFile(const std::string& path, std::vector<std::string>* warnings) {
  checkSceneFile(path);
  const std::string extension = lowerCaseExtension(path);
  if (extension == ".gltf" || extension == ".glb") return importGltf(path, warnings);
  if (extension == ".mgf") return importMgf(path, warnings);
  throw SceneError(path, "",
                   "has an unknown extension '" + extension + "': radmesh reads glTF 2.0 and MGF scenes",
                   acceptedForms());
}

}  // namespace

void checkSceneFile(const std::string& path) {
  const FileKind kind = fileKind(path);
  if (kind == FileKind::Missing)
    throw SceneError(path, "", "no such file, and not a built-in scene name", acceptedForms());
  if (kind == FileKind::Folder) throw SceneError(path, "", "is a directory, not a scene file", acceptedForms());
  if (kind == FileKind::Special)
    throw SceneError(path, "", "is not a regular file (" + fileKindName(kind) + "), not a scene file", acceptedForms());
  // Whatever it is named: read as a scene, it would fail for reasons that do not apply.
  if (fileStartsWith(path, kCheckpointSignature))
    throw SceneError(path, "", "is a radmesh checkpoint, not a scene",
                     "give it to --resume beside the scene it was written for (radmesh solve SCENE --resume " + path +
                         ")");
  // MGF and .gltf are text: read as text, a binary file is a stream of unknown entities.
  const std::string extension = lowerCaseExtension(path);
  if ((extension == ".mgf" || extension == ".gltf") && looksBinary(path))
    throw SceneError(path, "",
                     fileStartsWith(path, kGlbSignature) ? "is glTF binary (.glb), not " + extension.substr(1) + " text"
                                                         : "is a binary file, not " + extension.substr(1) + " text",
                     fileStartsWith(path, kGlbSignature) ? "name it .glb" : acceptedForms());
}

std::string lowerCaseExtension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

Scene loadScene(const std::string& pathOrName, std::vector<std::string>* warnings, const Daylight& daylight,
                std::vector<std::string>* notes, UpChoice up, std::vector<std::string>* readNotes,
                double metresPerUnit) {
  Scene scene = isBuiltinScene(pathOrName) ? builtinScene(pathOrName) : importFile(pathOrName, warnings);
  if (const DoubledPolygons doubled = dropDoubledPolygons(scene); doubled.dropped > 0 && warnings)
    warnings->push_back(fmt::format("{}: {} polygon(s) repeat an earlier one exactly (corners, side and material), "
                                    "the first {}: dropped, as copies would split the light falling there (one lit, "
                                    "one black)",
                                    pathOrName, doubled.dropped, doubled.first));
  scene.file = sceneFile(pathOrName);
  if (metresPerUnit > 0.0) {
    scaleScene(scene, metresPerUnit);
    if (const std::string implausible = implausibleUnitsWarning(scene, metresPerUnit, pathOrName);
        warnings && !implausible.empty())
      warnings->push_back(implausible);
  } else if (const std::string units = unitsNote(scene); readNotes && !units.empty())
    readNotes->push_back(units);
  // MGF does not say which axis is up, and files differ: office3 stands on y, the others on z.
  const bool silent = up == UpChoice::Format && lowerCaseExtension(pathOrName) == ".mgf";
  std::string note = applyUpChoice(scene, silent ? UpChoice::Auto : up);
  if (silent)
    note = std::string("MGF does not say which axis is up: ") + upAxisName(scene.upAxis) +
           ", from the geometry as --up auto decides (--up sets it)";
  if (readNotes && !note.empty()) readNotes->push_back(note);
  const UpFrame frame = upFrame(scene.upAxis);
  if (daylight.skyLux > 0.0) {
    validateGeometry(scene);  // openings are looked for in sound geometry only
    Daylight sky = daylight;
    sky.up = frame.up;
    std::vector<std::string> added = addSkyEmitters(scene, sky);
    if (notes) notes->insert(notes->end(), added.begin(), added.end());
  }
  for (Light sun : daylight.sun) {  // placed z up, y north: turned into the scene's up frame
    const Vec3 d = sun.direction;
    sun.direction = d.x * frame.across + d.y * frame.along + d.z * frame.up;
    scene.lights.push_back(sun);
  }
  validateScene(scene);
  return scene;
}

void refuseWarnings(const std::string& pathOrName, const std::vector<std::string>& warnings) {
  if (warnings.empty()) return;
  // Each warning starts with the file's name, which the error names once.
  const std::string prefix = pathOrName + ": ";
  const auto withoutFile = [&](const std::string& w) { return w.starts_with(prefix) ? w.substr(prefix.size()) : w; };
  const bool one = warnings.size() == 1;
  std::string problem = "refused under --strict (each warning an error)";
  problem += one ? ": " + withoutFile(warnings[0]) : fmt::format(", for its {} warnings:", warnings.size());
  if (!one)
    for (const std::string& w : warnings) problem += "\n  " + withoutFile(w);
  throw SceneError(pathOrName, "", problem,
                   fmt::format("correct what the {} name{}, or leave --strict out to open it as warned",
                               one ? "warning" : "warnings", one ? "s" : ""));
}

}  // namespace radmesh
