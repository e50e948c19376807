#pragma once
// The measurements behind docs/performance.md and docs/accuracy.md.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace radmesh::cli {

struct BenchSolveArgs {
  std::string scene = "office";
  double cellM = 0.381;
  std::vector<std::string> projections{"plane", "hemicube"};
  std::vector<int> resolutions{64, 128, 256, 512};
  double until = 0.95;
  int maxIterations = 5000;
  int threads = 1;
  std::vector<double> cells;  // patch-count scaling sweep; empty: skipped
  int scalingResolution = 256;
  int scalingIterations = 20;
};

nlohmann::json benchSolve(const BenchSolveArgs& args);

}  // namespace radmesh::cli
