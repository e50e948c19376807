#include "cli/solve_flags.h"

#include <algorithm>

#include "cli/scene_input.h"
#include "solver/meshing/meshing.h"
#include "solver/scene/scene_error.h"
#include "solver/io/scene_loader.h"

namespace radmesh::cli {

namespace {

void applyPresetFlags(Preset preset, SolveFlags& f) {
  applyPreset(preset, f.options);
  f.projection = toString(f.options.projection);
}

}  // namespace

SolveFlags::SolveFlags() { applyPresetFlags(Preset::Bake, *this); }

std::vector<std::string> SolveFlags::given() const {
  std::vector<std::string> names;
  for (const CLI::Option* option : solverOptions)
    if (option->count() > 0) names.push_back(option->get_name());
  return names;
}

SolveOptions SolveFlags::resolved() const {
  SolveOptions o = options;
  o.backend = parseBackend(backend);
  o.projection = parseProjection(projection);
  // The mesh back end runs the paper's single plane alone: asked for without a projection, it
  // takes that one rather than refusing the preset's hemicube.
  const std::vector<std::string> flags = given();
  if (o.backend == Backend::Mesh && std::find(flags.begin(), flags.end(), "--projection") == flags.end())
    o.projection = Projection::Plane;
  o.mapping = parseMapping(mapping);
  validateOptions(o);
  return o;
}

void addSolveFlags(CLI::App* cmd, SolveFlags& f) {
  cmd->add_option("scene", f.scene, "Built-in name (office, cornell, furnace, two-rooms) or a .gltf/.glb/.mgf file")
      ->capture_default_str();
  cmd->add_flag("--strict", f.strict, "Refuse a scene that needed any repair (each warning an error)");
  addUpOption(cmd, f.up);
  const size_t first = cmd->get_options().size();
  cmd->add_option_function<std::string>(
         "--preset", [&f](const std::string& name) { applyPresetFlags(parsePreset(name), f); },
         "bake (the default: hemicube 256, until 1 % of the power is unshot) or paper (Varshney & Prins: single "
         "plane 128, ratio 3, until C = 0.95); flags given beside it win")
      ->trigger_on_parse();
  cmd->add_option("--backend", f.backend, "native (host CPU) or mesh (emulated MasPar MP-1)")->capture_default_str();
  cmd->add_option("--cell", f.cellM, "Grid cell size for meshing, metres (the paper: 15 in)")->capture_default_str();
  cmd->add_option("--mapping", f.mapping, "Mesh backend: hierarchical, cut-and-stack or adaptive")->capture_default_str();
  cmd->add_option("--projection", f.projection, "plane (single plane), hemicube or analytic")->capture_default_str();
  cmd->add_option("--resolution", f.options.resolution, "N for an N x N projection plane, 16..2048")->capture_default_str();
  cmd->add_option("--ratio", f.options.ratio, "Half-side of the single plane at height 1")->capture_default_str();
  cmd->add_option("--shooters", f.options.shooters, "k patches shot per iteration")->capture_default_str();
  cmd->add_option("--until", f.options.until, "Stop at this convergence C (0..1]; 1: on the unshot power alone")->capture_default_str();
  cmd->add_option("--until-unshot", f.options.untilUnshot,
                  "Also stop when unshot power is this fraction of the emitted, e.g. 0.01 (0: off)")
      ->capture_default_str();
  cmd->add_option("--max-iterations", f.options.maxIterations, "Stop after this many iterations")->capture_default_str();
  cmd->add_option("--threads", f.options.threads, "Host threads; 0 uses every core")->capture_default_str();
  cmd->add_option_function<double>(
         "--cache-mb",
         [&f](double mb) {
           if (!(mb >= 0.0 && mb < 1e6)) throw OptionError("--cache-mb must be a size in MiB from 0 to 1e6");
           f.options.formFactorCacheBytes = static_cast<std::size_t>(mb * 1024 * 1024);
         },
         "Form-factor row cache budget in MiB (0: none)");
  const std::vector<CLI::Option*> options = cmd->get_options();
  f.solverOptions.assign(options.begin() + static_cast<std::ptrdiff_t>(first), options.end());
}

}  // namespace radmesh::cli
