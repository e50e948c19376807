#include "viewer/viewed_file.h"

#include "solver/io/scene_loader.h"
#include "solver/meshing/meshing.h"
#include "solver/radiosity/effects_plan.h"

namespace radmesh {

ViewedFile readViewedFile(const std::string& path, const ViewerArgs& args) {
  ViewedFile file;
  file.path = path;
  file.setup = args.setup;
  file.bake = readBake(path);
  std::vector<std::string> readNotes;
  if (file.bake) {
    file.scene = bakeScene(*file.bake, path);
    if (std::string chosen = applyUpChoice(file.scene, args.up); !chosen.empty()) readNotes.push_back(chosen);
    file.bake->upAxis = file.scene.upAxis;
  } else {
    file.scene =
        loadScene(path, &file.warnings, args.daylight, &file.notes, args.up, &readNotes, args.metresPerUnit);
    if (args.strict) refuseWarnings(path, file.warnings);
  }
  file.notes.insert(file.notes.end(), readNotes.begin(), readNotes.end());
  if (file.bake) return file;
  checkAnalyticSeesNoShadows(file.scene, file.setup.options.projection);
  if (!args.cellGiven) {
    const CellChoice cell = args.elementsPreset ? elementsPresetChoice(chooseCell(file.scene)) : chooseCell(file.scene);
    file.setup.cellM = cell.cellM;
    file.notes.push_back(cell.why);
  }
  if (args.elementsPreset && file.setup.options.subdivide == Subdivide::Uniform) {
    file.setup.options.minElementM = 0.25 * file.setup.cellM;
    file.notes.push_back(quarterMinElementNote(file.setup.options.minElementM));
  }
  return file;
}

std::string openFailure(const std::string& path, const std::string& error) {
  return "could not open " + (error.starts_with(path) ? error : path + ": " + error);
}

}  // namespace radmesh
