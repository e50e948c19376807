#include "cli/solve_flags.h"

#include <fmt/core.h>

#include <algorithm>

#include "cli/option_checks.h"
#include "cli/scene_input.h"
#include "solver/meshing/meshing.h"
#include "solver/scene/scene_error.h"
#include "solver/io/scene_loader.h"
#include "solver/scene/sun.h"

namespace radmesh::cli {

namespace {

void applyPresetFlags(Preset preset, SolveFlags& f) {
  applyPreset(preset, f.options);
  f.preset = preset;
  f.projection = toString(f.options.projection);
  f.subdivide = toString(f.options.subdivide);
}

bool contains(const std::vector<std::string>& flags, const std::string& flag) {
  return std::find(flags.begin(), flags.end(), flag) != flags.end();
}

}  // namespace

SolveFlags::SolveFlags() { applyPresetFlags(Preset::Bake, *this); }

std::vector<std::string> SolveFlags::given() const {
  std::vector<std::string> names;
  for (const CLI::Option* option : solverOptions)
    if (option->count() > 0) names.push_back(option->get_name());
  return names;
}

CellChoice SolveFlags::cell(const Scene& scene) const {
  const bool cellGiven = contains(given(), "--cell");
  const CellChoice chosen = commandCell(scene, cellM, cellGiven);
  return preset == Preset::Elements && !cellGiven ? elementsPresetChoice(chosen) : chosen;
}

CellChoice SolveFlags::announceCell(const Scene& scene, SolveOptions& options) const {
  const CellChoice chosen = cell(scene);
  fmt::print("{}\n", chosen.why);
  const bool presetElements =
      preset == Preset::Elements && options.subdivide == Subdivide::Uniform && !contains(given(), "--min-element");
  if (presetElements) options.minElementM = 0.25 * chosen.cellM;
  if (presetElements || defaultMinElement(options, chosen.cellM))
    fmt::print("{}\n", quarterMinElementNote(options.minElementM));
  return chosen;
}

CellChoice commandCell(const Scene& scene, double cellM, bool given) {
  if (given) checkCell(cellM);  // before it is announced
  return given ? CellChoice{cellM, fmt::format("cell {:.4g} m, as --cell gives", cellM)} : chooseCell(scene);
}

void addDaylightFlags(CLI::App* cmd, Daylight& daylight) {
  CLI::Option* sky = cmd->add_option_function<double>(
      "--sky",
      [&daylight](double lux) {
        checkSkyLux(lux);
        daylight.skyLux = lux;
      },
      "Light the scene by a sky of this horizontal illuminance (lux) through its openings");
  cmd->add_option_function<std::string>(
         "--sky-model", [&daylight](const std::string& name) { daylight.sky = parseSkyModel(name); },
         "The sky's luminance: uniform (the default) or cie-overcast (three times brighter at the zenith)")
      ->type_name("uniform|cie-overcast")
      ->needs(sky);  // without a sky it would shape nothing, without a word
  cmd->add_option_function<std::string>(
      "--sun", [&daylight](const std::string& text) { daylight.sun = {parseSun(text)}; },
      "Sunlight: AZIMUTH,ELEVATION[,LUX], degrees clockwise from north and above the horizon (north +y when z is up); LUX "
      "defaults to 100000, clear-sky direct sun. Combines with the scene's own lights and the sky");
}

SolveOptions SolveFlags::resolved() const {
  SolveOptions o = options;
  o.effects = parseEffects(effects);
  o.backend = parseBackend(backend);
  o.projection = parseProjection(projection);
  // The mesh back end runs the paper's single plane alone: asked for without a projection, it
  // takes that one rather than refusing the preset's hemicube.
  const std::vector<std::string> flags = given();
  if (o.backend == Backend::Mesh && !contains(flags, "--projection"))
    o.projection = Projection::Plane;
  o.mapping = parseMapping(mapping);
  o.subdivide = parseSubdivide(subdivide);
  refuseFlagsThatShapeNothing(flags, o, cellsOn());
  o.formFactorCacheBytes = formFactorCacheBytes(o.backend, cacheMb);
  // A bake and a render show what was solved. The display ambient term, which spreads the unshot
  // power evenly over every surface, lit a room sealed off from the only lamp (the viewer keeps it,
  // to show a solve under way).
  o.ambient = false;
  validateOptions(o);
  return o;
}

bool SolveFlags::cellsOn() const { return parseCells(cells); }


void addMachineFlags(CLI::App* cmd, PeMachine& machine) {
  cmd->add_option_function<std::string>(
      "--pe-grid", [&machine](const std::string& text) { parsePeGrid(text, machine); },
      "Mesh backend: the emulated machine's PE columns x rows, powers of two (default 64x64, the MP-1's)");
  cmd->add_option("--pe-memory", machine.memoryKb, "Mesh backend: each PE's memory in KB (the MP-1's 16)")
      ->capture_default_str();
}

void addSolveFlags(CLI::App* cmd, SolveFlags& f) {
  cmd->add_option("scene", f.scene, "Built-in name (office, cornell, furnace, two-rooms, building:COLSxROWS) or a .gltf/.glb/.mgf file")
      ->capture_default_str();
  const size_t first = cmd->get_options().size();
  cmd->add_flag("--strict", f.strict, kStrictHelp);
  addUpOption(cmd, f.up);
  addUnitsOption(cmd, f.metresPerUnit);
  addDaylightFlags(cmd, f.daylight);
  cmd->add_option_function<std::string>(
         "--preset", [&f](const std::string& name) { applyPresetFlags(parsePreset(name), f); },
         "bake (the default: hemicube 256, until 1 % of the power is unshot), paper (Varshney & Prins: single "
         "plane 128, ratio 3, until C = 0.95) or elements (the bake, a better picture in a third of its time or "
         "less: patches 2.625 x the cell shoot, elements a quarter of theirs receive); flags given beside it win")
      ->type_name("bake|paper|elements")
      ->trigger_on_parse();
  cmd->add_option("--effects", f.effects, "auto: simulate only what the scene calls for; all: everything")
      ->type_name("auto|all")
      ->capture_default_str();
  cmd->add_option("--backend", f.backend, "native (host CPU) or mesh (emulated MasPar MP-1)")
      ->type_name("native|mesh")
      ->capture_default_str();
  cmd->add_option("--cell", f.cellM, "Grid cell size for meshing, metres (default: chosen from the scene's size; the paper: 0.381)");
  cmd->add_option("--mapping", f.mapping, "Mesh backend: hierarchical, cut-and-stack or adaptive")
      ->type_name("hierarchical|cut-and-stack|adaptive")
      ->capture_default_str();
  addMachineFlags(cmd, f.options.machine);
  cmd->add_option("--projection", f.projection, "plane (single plane), hemicube or analytic")
      ->type_name("plane|hemicube|analytic")
      ->capture_default_str();
  cmd->add_option("--resolution", f.options.resolution, "N for an N x N projection plane, 16..2048")->capture_default_str();
  cmd->add_option("--ratio", f.options.ratio, kRatioHelp)->capture_default_str();
  cmd->add_option("--shooters", f.options.shooters, "k patches shot per iteration")->capture_default_str();
  cmd->add_option("--until", f.options.until, "Stop at this convergence C (0..1]; 1: on the unshot power alone")->capture_default_str();
  cmd->add_option("--until-unshot", f.options.untilUnshot, kUntilUnshotHelp)
      ->capture_default_str();
  cmd->add_option("--max-iterations", f.options.maxIterations, kMaxIterationsHelp)->capture_default_str();
  cmd->add_option("--threads", f.options.threads, "Host threads; 0 uses every core")->transform(threadCount("radmesh"))->capture_default_str();
  cmd->add_option_function<double>(
         "--cache-mb",
         [&f](double mb) { f.cacheMb = checkedCacheMb(mb); },
         kCacheMbHelp);
  cmd->add_option("--subdivide", f.subdivide,
                  "off (patches shoot and receive), uniform (patches shoot, their elements receive) or adaptive "
                  "(elements split where the light changes): docs/accuracy.md")
      ->type_name("off|uniform|adaptive")
      ->capture_default_str();
  cmd->add_option("--min-element", f.options.minElementM,
                  "With --subdivide uniform: longest element edge, metres (0: every patch cut into four); with "
                  "adaptive: no split makes elements shorter than this (0: a quarter of the cell)")
      ->capture_default_str();
  cmd->add_option_function<std::string>(
         "--element-rows", [&f](const std::string& text) { f.options.elementRows = parseElementRows(text); },
         "With --subdivide: share (native default: patches on the item buffer, each one's form factor shared "
         "among its elements by their analytic form factors and visible pixels) or rasterise (every element "
         "on the item buffer: the mesh back end's way), or auto (the back end's own: share on the host, "
         "rasterise on the mesh)")
      ->type_name("share|rasterise|auto");
  cmd->add_option("--split-contrast", f.options.splitContrast,
                  "With --subdivide adaptive: split neighbouring elements whose reflected radiosities differ by "
                  "more than this fraction of the brightest element's")
      ->capture_default_str();
  cmd->add_option_function<std::string>(
         "--split-shadows",
         [&f](const std::string& text) {
           if (text != "on" && text != "off")
             throw OptionError("--split-shadows must be on (split elements a shadow edge crosses) or off, not '" +
                               text + "'");
           f.options.splitShadows = text == "on";
         },
         "With --subdivide adaptive: on splits elements a shadow edge crosses (default), off only by contrast")
      ->type_name("on|off");
  cmd->add_option_function<std::string>(
         "--split-regather",
         [&f](const std::string& text) {
           if (text != "last" && text != "all")
             throw OptionError("--split-regather must be last (a split element's children receive the splitting "
                               "iteration's shots anew, inheriting the rest) or all (every shot so far), not '" +
                               text + "'");
           f.options.splitRegatherAll = text == "all";
         },
         "With --subdivide adaptive: last (default) or all: the shots a split element's children receive anew")
      ->type_name("last|all");
  cmd->add_option("--cells", f.cells,
                  "auto: find the rooms and solve cell by cell, light crossing at portals (docs/cells.md); off")
      ->type_name("auto|off")
      ->capture_default_str();
  addPortalExchangeOptions(cmd, f.exchangeShots, f.portalBins);
  const std::vector<CLI::Option*> options = cmd->get_options();
  f.solverOptions.assign(options.begin() + static_cast<std::ptrdiff_t>(first), options.end());
}

}  // namespace radmesh::cli
