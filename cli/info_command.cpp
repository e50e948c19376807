// `radmesh info SCENE`: what a scene holds and what meshing makes of it.
#include <fmt/core.h>

#include <nlohmann/json.hpp>

#include <ctime>
#include <utility>

#include "cli/counted.h"
#include "cli/commands.h"
#include "solver/io/output_path.h"
#include "cli/scene_input.h"
#include "cli/stats_json.h"
#include "cli/effects_text.h"
#include "solver/cells/find_cells.h"
#include "solver/formfactors/light_rows.h"
#include "cli/solve_flags.h"
#include "solver/radiosity/effects_plan.h"
#include "solver/meshing/elements.h"
#include "solver/meshing/meshing.h"
#include "solver/io/scene_loader.h"
#include "solver/meshing/scene_summary.h"
#include "solver/scene/scene_error.h"
#include "solver/scene/solve_options.h"

#if RADMESH_HAS_VIEWER
#include "viewer/cell_plan.h"
#endif

namespace radmesh::cli {

namespace {

struct InfoArgs {
  std::string scene = kDefaultScene;
  double cellM = kDefaultCellM;  // with --cell; else chooseCell's
  Daylight daylight;
  bool json = false;
  bool strict = false;
  UpChoice up = UpChoice::Format;
  double metresPerUnit = 0.0;  // --units; 0: not given
  EffectsMode effects = EffectsMode::Auto;
  std::string cells;  // --cells: "" (not given, or given alone), auto or off
  CellGroups cellGroups = CellGroups::Name;
  std::string planPath;  // --plan FILE.png
  double minElementM = 0.0;  // --min-element: the elements --subdivide uniform would make
};

// Per cell what a cell solve would hold: its patches, their area, its emitting patches and power.
struct CellFigures {
  long patches = 0;
  double areaM2 = 0.0;
  long emitters = 0;
  double emittedW = 0.0;
};

std::vector<CellFigures> cellFigures(const Scene& scene, const std::vector<Patch>& patches,
                                     const CellPartition& cells, CellFigures& outside) {
  std::vector<CellFigures> out(cells.cells.size());
  for (size_t i = 0; i < patches.size(); ++i) {
    const int c = cells.cellOfPatch[i];
    CellFigures& f = c >= 0 ? out[c] : outside;
    const Material& m = scene.materials[patches[i].material];
    ++f.patches;
    f.areaM2 += patches[i].areaM2;
    f.emitters += m.emits() ? 1 : 0;
    f.emittedW += patches[i].areaM2 * channelSum(m.emittance);
  }
  return out;
}

nlohmann::json cellsJson(const CellPartition& cells, const std::vector<CellFigures>& figures,
                         const CellFigures& outside, double seconds) {
  nlohmann::json list = nlohmann::json::array(), portals = nlohmann::json::array();
  for (size_t c = 0; c < cells.cells.size(); ++c) {
    const Cell& cell = cells.cells[c];
    const CellFigures& f = figures[c];
    list.push_back({{"name", cell.name},
                    {"patches", f.patches},
                    {"area_m2", f.areaM2},
                    {"emitters", f.emitters},
                    {"emitted_w", f.emittedW},
                    {"bounds_min", {cell.boundsMin.x, cell.boundsMin.y, cell.boundsMin.z}},
                    {"bounds_max", {cell.boundsMax.x, cell.boundsMax.y, cell.boundsMax.z}}});
  }
  for (const Portal& p : cells.portals) {
    nlohmann::json vertices = nlohmann::json::array();
    for (const Vec3& v : p.vertices) vertices.push_back({v.x, v.y, v.z});
    portals.push_back({{"cells", {p.cellA, p.cellB}}, {"area_m2", p.areaM2}, {"vertices", vertices}});
  }
  return {{"cells", list},
          {"portals", portals},
          {"outside_patches", outside.patches},
          {"cells_cpu_seconds", seconds}};
}

void printCells(const CellPartition& cells, const std::vector<CellFigures>& figures, const CellFigures& outside,
                double seconds) {
  fmt::print("cells           {} (found in {:.3g} s of CPU), {}, {} facing no cell\n", cells.cells.size(), seconds,
             counted(std::ssize(cells.portals), "portal"), counted(outside.patches, "patch", "patches"));
  fmt::print("  {:>5}  {:<16} {:>8} {:>10} {:>9} {:>10}\n", "cell", "name", "patches", "area m^2", "emitters",
             "emitted W");
  for (size_t c = 0; c < cells.cells.size(); ++c) {
    const CellFigures& f = figures[c];
    fmt::print("  {:>5}  {:<16} {:>8} {:>10.4g} {:>9} {:>10.4g}\n", c, cells.cells[c].name, f.patches, f.areaM2,
               f.emitters, f.emittedW);
  }
  fmt::print("  {:>6}  {:<14} {:>10}\n", "portal", "cells", "area m^2");
  for (size_t k = 0; k < cells.portals.size(); ++k) {
    const Portal& p = cells.portals[k];
    fmt::print("  {:>6}  {:<14} {:>10.4g}\n", k, fmt::format("{} -> {}", p.cellA, p.cellB), p.areaM2);
  }
}

void writePlan(const std::vector<Patch>& patches, const CellPartition& cells, int upAxis, const std::string& path) {
#if RADMESH_HAS_VIEWER
  writePng(drawCellPlan(patches, cells, upAxis), path);
#else
  (void)patches, (void)cells, (void)upAxis;
  throw SceneError(path, "", "--plan needs the PNG writer of the viewer, which this radmesh was built without",
                   "rebuild with -DRADMESH_BUILD_VIEWER=ON, or leave out --plan");
#endif
}

// Each of the model's turned grids: its axis, turn and how many polygons are meshed on it.
nlohmann::json gridTurnsJson(const Grids& grids) {
  nlohmann::json list = nlohmann::json::array();
  for (size_t t = 0; t < grids.turns.size(); ++t)
    if (!grids.turns[t].own)
      list.push_back({{"axis", std::string(1, "xyz"[grids.turns[t].axis])},
                      {"degrees", grids.turns[t].degrees()},
                      {"polygons", grids.outlinesOn(t)}});
  return list;
}

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
          {"grid_turn_degrees", s.grids.principal().degrees()},
          {"grid_turns", gridTurnsJson(s.grids)},
          {"own_grid_polygons", s.grids.outlinesOnOwnGrids()},
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

void printBounds(const Vec3& low, const Vec3& high) {
  const Vec3 size = high - low;
  // Digits down to the millimetre, at least four: at site coordinates (5e6 m) four made both corners
  // of a building read (5e+05, 5e+06, 0).
  const Vec3 far = glm::max(glm::abs(low), glm::abs(high));
  const double farthest = std::max({far.x, far.y, far.z});
  const int digits = std::clamp(static_cast<int>(std::ceil(std::log10(farthest / 0.001 + 1.0))), 4, 15);
  fmt::print("bounding box    ({:.{}g}, {:.{}g}, {:.{}g}) .. ({:.{}g}, {:.{}g}, {:.{}g}) m, size {:.4g} x {:.4g} x "
             "{:.4g} m\n",
             low.x, digits, low.y, digits, low.z, digits, high.x, digits, high.y, digits, high.z, digits, size.x,
             size.y, size.z);
}

// Of the lights' power, what never enters the model (the sun on its walls and roof, or past it), as
// a solve at the default (preset bake) resolution books it: emitted power alone overstates the light.
double lightOutsideW(const Scene& scene, const std::vector<Patch>& patches) {
  if (scene.lights.empty()) return 0.0;
  SolveOptions bake;
  applyPreset(Preset::Bake, bake);
  ThreadPool pool(0);
  return lightsPowerOutside(scene, patches, bake.resolution, pool);
}

void printText(const SceneSummary& s, const Scene& scene, const std::vector<std::string>& warnings,
               const std::vector<std::string>& notes, const CellChoice& cell, double lightOutside) {
  for (const std::string& w : warnings) fmt::print(stderr, "radmesh: warning: {}\n", w);
  for (const std::string& n : notes) fmt::print("{}\n", n);
  fmt::print("{}\n", cell.why);
  fmt::print("scene           {}\n", scene.source);
  fmt::print("up              {}\n", upAxisName(scene.upAxis));
  fmt::print("polygons        {}\n", s.polygons);
  fmt::print("patches         {} (cell {:.4g} m)\n", s.patches, s.cellM);
  for (size_t t = 0; t < s.grids.turns.size(); ++t) {
    const GridTurn& turn = s.grids.turns[t];
    if (turn.own) continue;
    const size_t polygons = s.grids.outlinesOn(t);
    fmt::print("grid            turned {:.6g} degrees about {} for {}\n", turn.degrees(), "xyz"[turn.axis],
               polygons == s.polygons ? fmt::format("all {} polygons", polygons)
                                                           : fmt::format("{} of {} polygons", polygons, s.polygons));
  }
  if (const size_t own = s.grids.outlinesOnOwnGrids())
    fmt::print("grid            its own for {} polygons, each at an angle to the model's grids\n", own);
  fmt::print("materials       {}\n", s.materials);
  fmt::print("emitters        {} polygons, {} patches\n", s.emitterPolygons, s.emitterPatches);
  if (s.lights > 0) fmt::print("lights          {} (no patch: each shoots once, first)\n", s.lights);
  printBounds(s.boundsMin, s.boundsMax);
  fmt::print("total area      {:.6g} m^2\n", s.totalAreaM2);
  fmt::print("emitted power   {:.6g} W (summed over RGB)\n", s.emittedPowerW);
  if (lightOutside > 0.0)
    fmt::print("                of it, {:.6g} W ({:.1f}%) is the lights' that falls on the model's outside or past it "
               "and never comes in, as a solve books it: {:.6g} W comes in\n",
               lightOutside, 100.0 * lightOutside / s.emittedPowerW, s.emittedPowerW - lightOutside);
}

// A bake has no materials, emitters or patches to tell of: its triangles, bounds, area and up axis.
void printBake(const std::string& path, const Bake& bake, bool json) {
  const std::vector<Polygon> triangles = bakeScene(bake, path).polygons;
  BoundingBox box = boundingBox(bake.mesh.positions);
  if (bake.mesh.positions.empty()) box = {Vec3(0.0), Vec3(0.0)};
  const Vec3 low = box.low, high = box.high;
  const double area = totalArea(triangles);
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
  cmd->add_option("scene", args->scene, "Built-in name (office, cornell, furnace, two-rooms, building:COLSxROWS) or a .gltf/.glb/.mgf file")
      ->capture_default_str();
  cmd->add_option("--cell", args->cellM, "Grid cell size for meshing, metres (default: chosen from the scene's size)");
  addDaylightFlags(cmd, args->daylight);
  cmd->add_flag("--json", args->json, "Print the same figures as JSON");
  cmd->add_flag("--strict", args->strict, kStrictHelp);
  addUpOption(cmd, args->up);
  addUnitsOption(cmd, args->metresPerUnit);
  cmd->add_option_function<std::string>(
      "--effects", [args](const std::string& v) { args->effects = parseEffects(v); },
      "auto (simulate only what the scene calls for) or all");
  cmd->add_option("--min-element", args->minElementM,
                  "Count the elements --subdivide uniform would cut the patches into, metres (0: four a patch)")
      ->capture_default_str();
  cmd->add_option("--cells", args->cells,
                  "auto (or --cells alone): also list the visibility cells (rooms) and the portals (openings) "
                  "joining them (docs/cells.md); off")
      ->type_name("auto|off")
      ->expected(0, 1);
  cmd->add_option("--plan", args->planPath, "Draw the cells' floor plan to this PNG (implies --cells)");
  cmd->add_option_function<std::string>(
         "--cell-groups",
         [args](const std::string& v) { args->cellGroups = v == "join" ? CellGroups::Join : CellGroups::Name; },
         "What the file's named groups (MGF o, built-in rooms) do: name (name the cells) or join (also "
         "make the cells of one group one cell)")
      ->check(CLI::IsMember({"name", "join"}));
  cmd->callback([args, cmd] {
    const bool known = args->cells.empty() || args->cells == "auto" || args->cells == "off";
    // --cells was a flag: in "info --cells SCENE" CLI11 takes the scene for --cells' value.
    if (!known && cmd->count("scene") == 0)
      args->scene = std::exchange(args->cells, "");
    else if (!known)
      throw OptionError("--cells '" + args->cells + "' is unknown: give auto (list the cells and portals, as --cells "
                        "alone does) or off");
    const bool cells = (cmd->count("--cells") > 0 && args->cells != "off") || !args->planPath.empty();
    // As CLI11's needs() refuses a flag that would shape nothing; --plan finds the cells too.
    if (cmd->count("--cell-groups") > 0 && !cells)
      throw OptionError("--cell-groups requires --cells (or --plan): it shapes the cells they find; add --cells, or "
                        "leave --cell-groups out");
    checkOutputPath("--plan", args->planPath, ".png", "the plan is a PNG picture");
    checkOutputsDistinct(args->scene, {{"--plan", args->planPath}});
    checkMinElement(args->minElementM);
    std::vector<std::string> sceneFlags;  // what shapes a scene's figures: all but the positional and --json
    for (const CLI::Option* option : cmd->get_options())
      if (option->count() > 0 && option->nonpositional() && option->get_name() != "--json")
        sceneFlags.push_back(option->get_name());
    if (const std::optional<Bake> bake = readCommandBake(args->scene, args->up, sceneFlags))
      return printBake(args->scene, *bake, args->json);
    std::vector<std::string> warnings, notes;
    const Scene scene =
        loadCommandScene(args->scene, args->strict, args->daylight, args->up, args->metresPerUnit, warnings, notes);
    const CellChoice cell = commandCell(scene, args->cellM, cmd->count("--cell") > 0);
    const std::vector<Patch> patches = meshScene(scene, cell.cellM);
    const SceneSummary summary = summarizeScene(scene, patches, cell.cellM);
    const EffectsPlan plan = planEffects(scene, patches, args->effects);
    const double elements = countElements(patches, args->minElementM);
    const double lightOutside = lightOutsideW(scene, patches);
    CellPartition partition;
    CellFigures outside;
    std::vector<CellFigures> figures;
    double seconds = 0.0;
    if (cells) {
      const std::clock_t start = std::clock();  // CPU time: findCells runs on one thread
      partition = findCells(scene, patches, args->cellGroups);
      seconds = double(std::clock() - start) / CLOCKS_PER_SEC;
      figures = cellFigures(scene, patches, partition, outside);
      if (!args->planPath.empty()) writePlan(patches, partition, scene.upAxis, args->planPath);
    }
    if (args->json) {
      nlohmann::json j = toJson(summary, scene);
      j["cell_m"] = cell.cellM;
      j["cell_why"] = cell.why;
      // A count, as "patches" is; a double only past what a count holds exactly (a --min-element of nothing).
      j["elements"] = elements < 9e15 ? nlohmann::json(static_cast<long long>(elements)) : nlohmann::json(elements);
      j["min_element"] = args->minElementM;
      j["element_limit"] = elementLimit().count;
      j["effects"] = effectsJson(plan);
      j["warnings"] = warnings;
      if (cells) j.update(cellsJson(partition, figures, outside, seconds));
      j["daylight"] = notes;
      j["metres_per_unit"] = args->metresPerUnit > 0.0 ? args->metresPerUnit : 1.0;
      j["light_outside"] = lightOutside;  // of emitted_power, as --stats' ledger books it
      if (!args->planPath.empty()) j["plan"] = args->planPath;  // what the text says as "wrote"
      fmt::print("{}\n", j.dump(2));
    } else {
      printText(summary, scene, warnings, notes, cell, lightOutside);
      fmt::print("elements        {:.0f} with --subdivide uniform --min-element {:g}{}{}\n", elements, args->minElementM,
                 args->minElementM == 0.0 ? " (every patch cut into four)" : "",
                 elements > static_cast<double>(elementLimit().count)
                     ? fmt::format(", more than this machine's limit of {}: a solve refuses it", elementLimit().count)
                     : "");
      printEffects(plan);
      if (cells) printCells(partition, figures, outside, seconds);
      if (!args->planPath.empty()) fmt::print("wrote {}\n", args->planPath);  // as every command that writes
    }
  });
}

}  // namespace radmesh::cli
