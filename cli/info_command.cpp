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
  EffectsMode effects = EffectsMode::Auto;
};

nlohmann::json toJson(const SceneSummary& s, const Scene& scene) {
  nlohmann::json materials = nlohmann::json::array();
  for (const Material& m : scene.materials)
    materials.push_back({{"name", m.name},
                         {"rho", {m.rho.r, m.rho.g, m.rho.b}},
                         {"emittance", {m.emittance.r, m.emittance.g, m.emittance.b}}});
  return {{"scene", scene.source},
          {"polygons", s.polygons},
          {"patches", s.patches},
          {"cell", s.cellM},
          {"materials", s.materials},
          {"material_list", materials},
          {"emitters", s.emitterPolygons},
          {"emitter_patches", s.emitterPatches},
          {"lights", s.lights},
          {"bounds_min", {s.boundsMin.x, s.boundsMin.y, s.boundsMin.z}},
          {"bounds_max", {s.boundsMax.x, s.boundsMax.y, s.boundsMax.z}},
          {"total_area", s.totalAreaM2},
          {"emitted_power", s.emittedPowerW}};
}

void printText(const SceneSummary& s, const Scene& scene, const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings) fmt::print(stderr, "radmesh: warning: {}\n", w);
  const Vec3 size = s.boundsMax - s.boundsMin;
  fmt::print("scene           {}\n", scene.source);
  fmt::print("polygons        {}\n", s.polygons);
  fmt::print("patches         {} (cell {:.4g} m)\n", s.patches, s.cellM);
  fmt::print("materials       {}\n", s.materials);
  fmt::print("emitters        {} polygons, {} patches\n", s.emitterPolygons, s.emitterPatches);
  if (s.lights > 0) fmt::print("lights          {} (no patch: each shoots once, first)\n", s.lights);
  fmt::print("bounding box    ({:.4g}, {:.4g}, {:.4g}) .. ({:.4g}, {:.4g}, {:.4g}) m, size {:.4g} x {:.4g} x {:.4g} m\n",
             s.boundsMin.x, s.boundsMin.y, s.boundsMin.z, s.boundsMax.x, s.boundsMax.y, s.boundsMax.z,
             size.x, size.y, size.z);
  fmt::print("total area      {:.6g} m^2\n", s.totalAreaM2);
  fmt::print("emitted power   {:.6g} W (summed over RGB)\n", s.emittedPowerW);
}

}  // namespace

void addInfoCommand(CLI::App& app) {
  auto args = std::make_shared<InfoArgs>();
  CLI::App* cmd = app.add_subcommand("info", "Print a scene's polygons, patches, materials, emitters, bounds, area and power");
  cmd->add_option("scene", args->scene, "Built-in name (office, cornell, furnace, two-rooms) or a .gltf/.glb/.mgf file")
      ->capture_default_str();
  cmd->add_option("--cell", args->cellM, "Grid cell size for meshing, metres")->capture_default_str();
  cmd->add_flag("--json", args->json, "Print the same figures as JSON");
  cmd->add_flag("--strict", args->strict, "Refuse a scene that needed any repair (each warning an error)");
  cmd->add_option_function<std::string>(
      "--effects", [args](const std::string& v) { args->effects = parseEffects(v); },
      "auto (simulate only what the scene calls for) or all");
  cmd->callback([args] {
    std::vector<std::string> warnings;
    const Scene scene = loadCommandScene(args->scene, args->strict, warnings);
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
