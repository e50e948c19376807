// `radmesh info SCENE`: what a scene holds and what meshing makes of it.
#include <fmt/core.h>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/scene_input.h"
#include "cli/stats_json.h"
#include "cli/effects_text.h"
#include "solver/radiosity/effects_plan.h"
#include "solver/meshing/meshing.h"
#include "solver/io/scene_loader.h"
#include "solver/meshing/scene_summary.h"

namespace radmesh::cli {

namespace {

struct InfoArgs {
  std::string scene = kDefaultScene;
  double cellM = kDefaultCellM;
  bool json = false;
  bool strict = false;
  UpChoice up = UpChoice::Format;
  EffectsMode effects = EffectsMode::Auto;
};

nlohmann::json toJson(const SceneSummary& s, const Scene& scene) {
  nlohmann::json materials = nlohmann::json::array();
  for (const Material& m : scene.materials)
    materials.push_back({{"name", m.name},
                         {"rho", {m.rho.r, m.rho.g, m.rho.b}},
                         {"emittance", {m.emittance.r, m.emittance.g, m.emittance.b}}});
  return {{"scene", scene.source},
          {"kind", "scene"},
          {"up", upAxisName(scene.upAxis)},
          {"polygons", s.polygons},
          {"patches", s.patches},
          {"cell", s.cellM},
          {"materials", s.materials},
          {"material_list", materials},
          {"emitters", s.emitterPolygons},
          {"emitter_patches", s.emitterPatches},
          {"bounds_min", {s.boundsMin.x, s.boundsMin.y, s.boundsMin.z}},
          {"bounds_max", {s.boundsMax.x, s.boundsMax.y, s.boundsMax.z}},
          {"total_area", s.totalAreaM2},
          {"emitted_power", s.emittedPowerW}};
}

void printBounds(const Vec3& low, const Vec3& high) {
  const Vec3 size = high - low;
  fmt::print("bounding box    ({:.4g}, {:.4g}, {:.4g}) .. ({:.4g}, {:.4g}, {:.4g}) m, size {:.4g} x {:.4g} x {:.4g} m\n",
             low.x, low.y, low.z, high.x, high.y, high.z, size.x, size.y, size.z);
}

void printText(const SceneSummary& s, const Scene& scene, const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings) fmt::print(stderr, "radmesh: warning: {}\n", w);
  fmt::print("scene           {}\n", scene.source);
  fmt::print("up              {}\n", upAxisName(scene.upAxis));
  fmt::print("polygons        {}\n", s.polygons);
  fmt::print("patches         {} (cell {:.4g} m)\n", s.patches, s.cellM);
  fmt::print("materials       {}\n", s.materials);
  fmt::print("emitters        {} polygons, {} patches\n", s.emitterPolygons, s.emitterPatches);
  printBounds(s.boundsMin, s.boundsMax);
  fmt::print("total area      {:.6g} m^2\n", s.totalAreaM2);
  fmt::print("emitted power   {:.6g} W (summed over RGB)\n", s.emittedPowerW);
}

// A bake has no materials, emitters or patches to tell of: its triangles, bounds, area and up axis.
void printBake(const std::string& path, const Bake& bake, bool json) {
  const std::vector<Polygon> triangles = bakeScene(bake, path).polygons;
  Vec3 low(0.0), high(0.0);
  if (!bake.mesh.positions.empty()) low = high = bake.mesh.positions[0];
  for (const Vec3& p : bake.mesh.positions) low = glm::min(low, p), high = glm::max(high, p);
  double area = 0.0;
  for (const Polygon& t : triangles) area += polygonArea(t.vertices);
  const std::string up = upAxisName(bake.upAxis);
  const std::string by = bake.fromRadmesh ? "radmesh" : "another tool";
  if (json) {
    const nlohmann::json j = {{"scene", path},
                              {"kind", "bake"},
                              {"made_by", by},
                              {"up", up},
                              {"source_up", bake.sourceUp >= 0 ? nlohmann::json(upAxisName(bake.sourceUp)) : nullptr},
                              {"triangles", triangles.size()},
                              {"vertices", bake.mesh.positions.size()},
                              {"bounds_min", {low.x, low.y, low.z}},
                              {"bounds_max", {high.x, high.y, high.z}},
                              {"total_area", area},
                              {"radiosity_per_color_unit", bake.radiosityPerColorUnit},
                              {"warnings", nlohmann::json::array()}};
    fmt::print("{}\n", j.dump(2));
    return;
  }
  fmt::print("bake            {} (by {}; walk it with radmesh-view, render it with radmesh render)\n", path, by);
  fmt::print("up              {}{}\n", up,
             bake.sourceUp >= 0 ? fmt::format(" (the scene's {} turned onto glTF's y)", upAxisName(bake.sourceUp)) : "");
  fmt::print("triangles       {} ({} vertices)\n", triangles.size(), bake.mesh.positions.size());
  printBounds(low, high);
  fmt::print("total area      {:.6g} m^2\n", area);
  fmt::print("radiosity       COLOR_0 of 1 is {:.6g} W/m^2\n", bake.radiosityPerColorUnit);
}

}  // namespace

void addInfoCommand(CLI::App& app) {
  auto args = std::make_shared<InfoArgs>();
  CLI::App* cmd = app.add_subcommand("info", "Print a scene's polygons, patches, materials, emitters, bounds, area, power and up axis (or a bake's triangles, bounds, area and up axis)");
  cmd->add_option("scene", args->scene, "Built-in name (office, cornell, furnace, two-rooms) or a .gltf/.glb/.mgf file")
      ->capture_default_str();
  cmd->add_option("--cell", args->cellM, "Grid cell size for meshing, metres")->capture_default_str();
  cmd->add_flag("--json", args->json, "Print the same figures as JSON");
  cmd->add_flag("--strict", args->strict, "Refuse a scene that needed any repair (each warning an error)");
  addUpOption(cmd, args->up);
  cmd->add_option_function<std::string>(
      "--effects", [args](const std::string& v) { args->effects = parseEffects(v); },
      "auto (simulate only what the scene calls for) or all");
  cmd->callback([args] {
    if (const std::optional<Bake> bake = readCommandBake(args->scene, args->up)) return printBake(args->scene, *bake, args->json);
    std::vector<std::string> warnings;
    const Scene scene = loadCommandScene(args->scene, args->strict, args->up, warnings);
    const std::vector<Patch> patches = meshScene(scene, args->cellM);
    const SceneSummary summary = summarizeScene(scene, patches, args->cellM);
    const EffectsPlan plan = planEffects(scene, patches, args->effects);
    if (args->json) {
      nlohmann::json j = toJson(summary, scene);
      j["effects"] = effectsJson(plan);
      j["warnings"] = warnings;
      fmt::print("{}\n", j.dump(2));
    } else {
      printText(summary, scene, warnings);
      printEffects(plan);
    }
  });
}

}  // namespace radmesh::cli
