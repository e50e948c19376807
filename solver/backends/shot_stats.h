#pragma once
// What one shot did on the machine a back end runs on, in a form that the solver's history,
// `--stats`, the panel and the benches carry and show without knowing which back end it was: the
// machine's clock, typed, and every other figure as a JSON tree under the back end's own keys.
// A back end without figures (the native one) reports none.
#include <nlohmann/json.hpp>
#include <string>

namespace radmesh {

struct ShotStats {
  std::string machine;          // what the shot ran on, e.g. "emulated MP-1"; names its seconds
  double machineSeconds = 0.0;  // the shot's time on that machine
  // Per-iteration figures as `--stats` writes them: numbers, histograms (arrays of counts),
  // tables (arrays of objects with the same keys) and groups (objects).
  nlohmann::json figures = nlohmann::json::object();
};

}  // namespace radmesh
