#pragma once
// The flags `radmesh render` and `radmesh-view` share: where the view starts, and its exposure.
// Header-only: radmesh-view compiles it without the radmesh command's sources.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "solver/scene/scene_error.h"
#include "viewer/camera.h"
#include "viewer/exposure.h"

namespace radmesh::cli {

// "X,Y,Z": three finite numbers and nothing after them; else OptionError naming `option`.
inline glm::dvec3 parsePoint(const std::string& text, const char* option) {
  glm::dvec3 p;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%lf,%lf,%lf%c", &p.x, &p.y, &p.z, &tail) != 3 || !std::isfinite(p.x) ||
      !std::isfinite(p.y) || !std::isfinite(p.z))
    throw OptionError(fmt::format("{} '{}' is not a point: give three numbers in metres as X,Y,Z", option, text));
  return p;
}

// Adds --camera, --look and --exposure.
inline void addViewFlags(CLI::App* cmd, ViewStart& start, std::optional<double>& exposureEv) {
  cmd->add_option_function<std::string>(
      "--camera", [&start](const std::string& text) { start.eye = parsePoint(text, "--camera"); },
      "Eye position X,Y,Z in metres, in the file's own axes: a scene's as read (after --units; --up does not turn "
      "them), a bake's y-up ones as written, not its scene's (default: the walkthrough's start)");
  cmd->add_option_function<std::string>(
      "--look", [&start](const std::string& text) { start.look = parsePoint(text, "--look"); },
      "Point looked at X,Y,Z, in --camera's axes (default: the start's direction; with --camera, the scene's "
      "centre)");
  cmd->add_option_function<double>(
      "--exposure",
      [&exposureEv](double ev) {
        // As far as any automatic exposure it reports goes, so that it can be given back; beyond, a typo.
        if (!(std::abs(ev) <= kMaxExposureStops))
          throw OptionError(fmt::format("--exposure {} is out of range: give stops from {} to {}, e.g. -2 (or leave "
                                        "it out: automatic)",
                                        ev, -kMaxExposureStops, kMaxExposureStops));
        exposureEv = ev;
      },
      "Exposure in stops: shown value = B x 2^EV, white at 1 (default: automatic)");
}

}  // namespace radmesh::cli
