#include "solver/io/builtin_scenes.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "solver/io/builtin_building.h"
#include "solver/io/builtin_office.h"
#include "solver/io/gltf_import.h"
#include "solver/io/scene_builder.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

namespace {

// A closed 1 m cube seen from inside, every face grey (rho 0.5) and emitting 1 W/m^2: the exact
// radiosity is B = E / (1 - rho) = 2 W/m^2 everywhere (the "white furnace" check of eq. 1.1 with
// every row of form factors summing to 1).
Scene furnaceScene() {
  SceneBuilder b("furnace");
  const int grey = b.addMaterial("furnace grey", Rgb(0.5), Rgb(1.0));
  b.addRoom({0, 0, 0}, {1, 1, 1}, {grey, grey, grey}, {}, "furnace");
  return b.take();
}

// Two 4 m x 4 m x 2.7 m rooms side by side, joined through a 0.2 m thick wall by a door-sized
// passage; only the first has a light. Closed: all light stays in the two rooms.
Scene twoRoomsScene() {
  SceneBuilder b("two-rooms");
  const int wall = b.addMaterial("wall paint", {0.72, 0.70, 0.65});
  const int floor = b.addMaterial("floor", {0.35, 0.30, 0.25});
  const int ceiling = b.addMaterial("ceiling", {0.80, 0.80, 0.78});
  const int light = b.addMaterial("light panel", {0.80, 0.80, 0.80}, {10.0, 9.6, 8.8});
  const RoomMaterials materials{floor, ceiling, wall};
  const double wallM = 0.2, y0 = 1.55, y1 = 2.45, doorZ = 2.1;
  b.addRoom({0, 0, 0}, {4, 4, 2.7}, materials,
            {{kXMax, {4, y0, 0}, {4, y1, doorZ}, wallM, -1, -1, "door"},
             {kZMax, {1.4, 1.7, 2.7}, {2.6, 2.3, 2.7}, 0.0, -1, light, "light"}},
            "first");
  b.addRoom({4 + wallM, 0, 0}, {8 + wallM, 4, 2.7}, materials,
            {{kXMin, {4 + wallM, y0, 0}, {4 + wallM, y1, doorZ}, 0.0, -1, -1, "door"}}, "second");
  return b.take();
}

// Where the built-in assets are: an `assets` folder beside the installed program's folder
// (prefix/bin/radmesh -> prefix/assets), else the source tree's, fixed at build time.
std::filesystem::path assetPath(const std::string& file) {
  std::error_code error;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const std::filesystem::path installed = exe.parent_path().parent_path() / "assets" / file;
    if (std::filesystem::exists(installed, error)) return installed;
  }
  return std::filesystem::path(RADMESH_ASSET_DIR) / file;
}

Scene cornellScene() {
  const std::filesystem::path path = assetPath("cornell.gltf");
  if (!std::filesystem::exists(path))
    throw SceneError(path.string(), "", "the built-in Cornell box asset is missing",
                     "reinstall radmesh, or run it from its build tree, so that assets/cornell.gltf exists");
  Scene scene = importGltf(path.string());
  scene.source = "cornell (" + path.string() + ")";
  scene.file = path.string();
  return scene;
}

}  // namespace

const std::vector<std::string>& builtinSceneNames() {
  static const std::vector<std::string> names{"office", "cornell", "furnace", "two-rooms"};
  return names;
}

std::string builtinSceneForms() {
  std::string known;
  for (const std::string& n : builtinSceneNames()) known += n + ", ";
  return known + std::string(kBuildingPrefix) + "COLSxROWS";
}

bool isBuiltinScene(const std::string& name) {
  const auto& names = builtinSceneNames();
  return std::find(names.begin(), names.end(), name) != names.end() || name.rfind(kBuildingPrefix, 0) == 0;
}

std::string sceneFile(const std::string& pathOrName) {
  if (pathOrName == "cornell") return assetPath("cornell.gltf").string();
  return isBuiltinScene(pathOrName) ? "" : pathOrName;
}

Scene builtinScene(const std::string& name) {
  if (name == "office") return officeScene();
  if (name == "cornell") return cornellScene();
  if (name == "furnace") return furnaceScene();
  if (name == "two-rooms") return twoRoomsScene();
  if (name.rfind(kBuildingPrefix, 0) == 0) return buildingScene(parseBuildingName(name));
  throw SceneError(name, "", "is not a built-in scene",
                   "use one of " + builtinSceneForms() + ", or a .gltf, .glb or .mgf file");
}

}  // namespace radmesh
