#include "solver/radiosity/checkpoint_identity.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "solver/radiosity/checkpoint.h"
#include "solver/radiosity/checkpoint_io.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

namespace {

// The options that change the answer (--until, --max-iterations, --threads and the display-only
// ambient term do not; --cache-mb does on the mesh back end, where a row computed beside other
// shooters differs in its last bits).
OptionList answerOptions(const SolveOptions& o) {
  OptionList list = {{"--backend", toString(o.backend)},
                     {"--projection", toString(o.projection)},
                     {"--resolution", std::to_string(o.resolution)},
                     {"--ratio", fmt::format("{}", o.ratio)},  // shortest text that reads back bitwise
                     {"--shooters", std::to_string(o.shooters)},
                     {"--effects", toString(o.effects)},
                     {"sub-pixel receivers", o.subPixelReceivers ? "on" : "off"}};
  if (o.backend == Backend::Mesh) {
    list.push_back({"--mapping", toString(o.mapping)});
    // The machine's size orders the form factors' sums (and its counts are the saved state); the
    // MP-1's is left out, so that checkpoints from before --pe-grid still resume.
    if (o.machine.cols != PeMachine{}.cols || o.machine.rows != PeMachine{}.rows)
      list.push_back({"--pe-grid", peGridText(o.machine)});
    list.push_back({"--cache-mb", fmt::format("{}", o.formFactorCacheBytes / 1048576.0)});
  }
  list.push_back({"--subdivide", toString(o.subdivide)});
  if (o.subdivide != Subdivide::Off) {
    list.push_back({"--min-element", fmt::format("{}", o.minElementM)});
    list.push_back({"--element-rows", toString(resolvedElementRows(o))});
  }
  if (o.subdivide == Subdivide::Adaptive) {
    list.push_back({"--split-contrast", fmt::format("{}", o.splitContrast)});
    list.push_back({"--split-shadows", o.splitShadows ? "on" : "off"});
    list.push_back({"--split-regather", o.splitRegatherAll ? "all" : "last"});
  }
  return list;
}

// An option answerOptions leaves out: the MP-1's PE grid, or one the solve does not use.
std::string absentValue(const std::string& flag) {
  return flag == "--pe-grid" ? peGridText(PeMachine{}) : "not used";
}

// "--resolution 128 there, 256 here; ..." for the options that differ; empty if none.
std::string optionDifferences(const OptionList& saved, const OptionList& now) {
  auto valueIn = [](const OptionList& list, const std::string& flag) {
    for (const auto& [listed, value] : list)
      if (listed == flag) return value;
    return absentValue(flag);
  };
  std::string text;
  auto compare = [&](const std::string& flag) {
    const std::string there = valueIn(saved, flag), here = valueIn(now, flag);
    if (there != here) text += fmt::format("{}{} {} there, {} here", text.empty() ? "" : "; ", flag, there, here);
  };
  for (const auto& option : now) compare(option.first);
  for (const auto& option : saved)  // set there, absent here
    if (std::none_of(now.begin(), now.end(), [&](const auto& listed) { return listed.first == option.first; }))
      compare(option.first);
  return text;
}

// The preset whose options, on the back end the checkpoint was written on, are the saved ones:
// "--preset bake, on the native back end" (the viewer's own defaults are no preset's, and a
// solve's checkpoint needs --preset bake there); empty if none's are. `now` lists `options`,
// and a cells solve's settings after them.
std::string presetWritten(const OptionList& saved, const OptionList& now, const SolveOptions& options) {
  SolveOptions written = options;
  for (const auto& [flag, value] : saved)
    if (flag == "--backend") written.backend = parseBackend(value);
  written.formFactorCacheBytes = formFactorCacheBytes(written.backend, std::nullopt);
  const OptionList plain = answerOptions(options);
  for (const Preset preset : {Preset::Bake, Preset::Paper, Preset::Elements}) {
    SolveOptions given = written;
    applyPreset(preset, given);
    OptionList candidate = answerOptions(given);
    for (const auto& option : now)  // a cells solve's settings
      if (std::none_of(plain.begin(), plain.end(), [&](const auto& listed) { return listed.first == option.first; }))
        candidate.push_back(option);
    if (optionDifferences(saved, candidate).empty())
      return fmt::format("--preset {}{}", toString(preset),
                         written.backend == options.backend ? "" : fmt::format(", on the {} back end", toString(written.backend)));
  }
  return {};
}

}  // namespace

std::uint64_t meshedSceneHash(const Scene& scene, const std::vector<Patch>& patches) {
  std::uint64_t hash = checkpoint_io::fnv1a(nullptr, 0);
  auto add = [&](const auto& value) { hash = checkpoint_io::fnv1a(&value, sizeof value, hash); };
  add(static_cast<std::uint64_t>(patches.size()));
  for (const Patch& p : patches) {
    add(p.vertexCount);
    for (int v = 0; v < p.vertexCount; ++v)
      for (int axis = 0; axis < 3; ++axis) add(p.vertices[v][axis]);
    const Material& m = scene.materials.at(p.material);
    for (int c = 0; c < 3; ++c) add(m.rho[c]);
    for (int c = 0; c < 3; ++c) add(m.emittance[c]);
  }
  // The lights (none: the hash of a scene without them, as before they existed).
  for (const Light& l : scene.lights) {
    add(static_cast<int>(l.type));
    for (int axis = 0; axis < 3; ++axis) add(l.position[axis]), add(l.direction[axis]), add(l.intensity[axis]);
    add(l.innerConeRad);
    add(l.outerConeRad);
  }
  return hash;
}

Identity identityOf(const ProgressiveSolver& solver) {
  return {meshedSceneHash(solver.scene(), solver.patches()), solver.scene().source, solver.patches().size(),
          answerOptions(solver.options())};
}

Identity identityOf(const Scene& scene, const CellSolver& solver) {
  const CellSolveSettings& cells = solver.settings();
  OptionList options = answerOptions(solver.options());
  options.insert(options.end(), {{"--cells", "auto"},
                                 {"--cell", fmt::format("{}", cells.cellM)},
                                 {"--exchange-shots", std::to_string(cells.exchangeShots)},
                                 {"--portal-bins", std::to_string(cells.portalBins)}});
  return {meshedSceneHash(scene, solver.patches()), scene.source, solver.patches().size(), std::move(options)};
}

void checkSameSolve(const std::string& path, const Identity& was, const Identity& now, const SolveOptions& options) {
  if (was.sceneHash != now.sceneHash || was.patches != now.patches) {
    // The same name and count: the scene was placed, scaled or lit otherwise (--up, --units, daylight).
    const std::string scenes = was.sceneSource == now.sceneSource && was.patches == now.patches
                                   ? fmt::format("{}, {} patches, placed, scaled or lit otherwise", was.sceneSource, was.patches)
                                   : fmt::format("{}, {} patches; here {}, {} patches", was.sceneSource, was.patches,
                                                 now.sceneSource, now.patches);
    throw SceneError(path, "",
                  fmt::format("was written for another meshed scene ({}): the patches' vertices, materials or "
                              "emission, or the lights, differ",
                              scenes),
                  "resume with the scene, --cell, --units, --up and daylight (--sky, --sun) it was written with, or "
                  "solve from scratch without --resume");
  }
  if (const std::string differences = optionDifferences(was.options, now.options); !differences.empty()) {
    const std::string preset = presetWritten(was.options, now.options, options);
    throw SceneError(path, "", "was written with other options: " + differences,
                  preset.empty() ? "resume with the options it was written with, or solve from scratch without --resume"
                                 : fmt::format("resume with the options it was written with ({}), or solve from "
                                               "scratch without --resume",
                                               preset));
  }
}

}  // namespace radmesh
