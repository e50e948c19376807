// The layering docs/architecture.md draws, checked on the sources: each stage of solver/ includes
// only the stages before it, the back ends do not include each other, nothing but the factory
// sees a back end's own folder (the rest, the CLI, the viewer and the benches included, goes
// through FormFactorBackend and ShotStats), only the mesh back end sees the emulator (and
// distributed/, which makes its MPI transport), and the core
// never sees the viewer, the CLI or GL.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "tests/test_paths.h"

namespace radmesh {
namespace {

// The stages in data-flow order (docs/architecture.md).
const std::vector<std::string> kStages = {"scene",      "geometry",    "io",       "meshing",   "cells",
                                          "projection", "formfactors", "backends", "radiosity", "bake"};

struct Include {
  std::string file;    // relative to the project root, e.g. solver/io/mgf_import.cpp
  std::string target;  // as written, e.g. solver/scene/scene.h
};

std::string stageOf(const std::string& path) {  // "solver/backends/mesh/x.h" -> "backends"
  const auto first = path.find('/');
  const auto second = path.find('/', first + 1);
  return second == std::string::npos ? "" : path.substr(first + 1, second - first - 1);
}

std::string topFolder(const std::string& path) { return path.substr(0, path.find('/')); }

bool startsWith(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

// "solver/backends/mesh/x.h" -> "mesh"; "" outside a back end's own folder.
std::string backendOf(const std::string& path) {
  const std::string prefix = "solver/backends/";
  if (!startsWith(path, prefix)) return "";
  const auto slash = path.find('/', prefix.size());
  return slash == std::string::npos ? "" : path.substr(prefix.size(), slash - prefix.size());
}

// The one place besides a back end's own folder that includes it: the factory.
const std::string kFactory = "solver/backends/form_factor_backend.cpp";
// Programs that show the emulated machine itself, not radiosity on it.
const std::vector<std::string> kShowTheMachine = {"bench/emulator_bench.cpp"};

// One message per include that breaks the layering; empty when it holds.
std::vector<std::string> layeringViolations(const std::vector<Include>& includes) {
  std::vector<std::string> out;
  auto order = [](const std::string& stage) {
    return std::find(kStages.begin(), kStages.end(), stage) - kStages.begin();
  };
  for (const auto& [file, target] : includes) {
    const std::string from = topFolder(file);
    const std::string to = topFolder(target);
    auto bad = [&](const std::string& why) { out.push_back(file + " includes " + target + ": " + why); };
    const bool project = to == "solver" || to == "emulator" || to == "parallel" || to == "viewer" || to == "cli";
    const bool graphics = startsWith(target, "GL") || startsWith(target, "GLFW") || startsWith(target, "imgui") ||
                          startsWith(target, "glad");
    if (from == "parallel" && project && to != "parallel") bad("parallel/ knows nothing of the rest");
    if (from == "emulator" && project && to != "emulator" && to != "parallel")
      bad("the emulator knows nothing of radiosity");
    if (from == "solver" && (to == "viewer" || to == "cli" || graphics)) bad("the core has no GL and no UI");
    if (from == "solver" && (to == "distributed" || target == "mpi.h" || startsWith(target, "parallel/mpi/")))
      bad("the core knows no MPI: distributed/ is its MPI side");
    const bool showsTheMachine = std::count(kShowTheMachine.begin(), kShowTheMachine.end(), file) > 0;
    // distributed/ makes the machine's MPI transport (the solver gets it as an emu::Transport).
    if (to == "emulator" && from != "emulator" && from != "parallel" && from != "distributed" &&
        !startsWith(file, "solver/backends/mesh/") && !showsTheMachine)
      bad("only the mesh back end sees emulator types");
    if (!backendOf(target).empty() && backendOf(file).empty() && file != kFactory)
      bad("a back end's folder is its own: the rest uses FormFactorBackend and ShotStats");
    if (from != "solver") continue;
    const std::string stage = stageOf(file);
    if (order(stage) == static_cast<long>(kStages.size())) {
      bad("solver/ files live in one of the stage folders");
      continue;
    }
    if (to != "solver") continue;
    if (order(stageOf(target)) > order(stage)) bad("a stage includes only the stages before it");
    const std::string fromBackend = backendOf(file), toBackend = backendOf(target);
    if (!fromBackend.empty() && !toBackend.empty() && fromBackend != toBackend)
      bad("one back end does not include another");
  }
  return out;
}

std::vector<Include> includesUnder(const std::filesystem::path& root, const std::vector<std::string>& folders) {
  const std::regex includeLine(R"(^\s*#\s*include\s*[<"]([^>"]+)[>"])");
  std::vector<Include> out;
  for (const auto& folder : folders) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root / folder)) {
      const auto ext = entry.path().extension();
      if (ext != ".h" && ext != ".cpp") continue;
      std::ifstream in(entry.path());
      const std::string file = std::filesystem::relative(entry.path(), root).generic_string();
      std::smatch m;
      for (std::string line; std::getline(in, line);)
        if (std::regex_search(line, m, includeLine)) out.push_back({file, m[1]});
    }
  }
  return out;
}

TEST(Layering, TheSourcesKeepIt) {
  const auto includes = includesUnder(test::sourceDir(), {"parallel", "emulator", "solver", "cli", "viewer", "bench", "distributed"});
  ASSERT_GT(includes.size(), 300u);  // the walk found the sources
  const auto violations = layeringViolations(includes);
  std::string all;
  for (const auto& v : violations) all += v + "\n";
  EXPECT_TRUE(violations.empty()) << all;
}

TEST(Layering, EachRuleCatchesItsBreak) {
  const std::vector<Include> broken = {
      {"solver/scene/scene.cpp", "solver/meshing/patch.h"},                    // a later stage
      {"solver/backends/mesh/mesh_backend.cpp", "solver/backends/native/native_backend.h"},  // a sibling
      {"solver/radiosity/progressive_solver.h", "emulator/mesh_machine.h"},    // emulator type in the seam
      {"emulator/router.cpp", "solver/scene/scene.h"},                         // emulator sees radiosity
      {"solver/bake/gltf_export.cpp", "GLFW/glfw3.h"},                         // GL in the core
      {"solver/stray.cpp", "solver/scene/scene.h"},                            // outside the stages
      {"parallel/thread_pool.cpp", "emulator/xnet.h"},
      {"solver/backends/form_factor_backend.h", "solver/backends/mesh/mesh_shot_stats.h"},  // a back end in the seam
      {"cli/stats_json.cpp", "solver/backends/mesh/mesh_shot_stats.h"},      // a back end outside the factory
      {"bench/mesh_backend_bench.cpp", "solver/backends/native/native_backend.h"},
      {"viewer/solver_snapshot.h", "emulator/cost_counts.h"},                // emulator outside the mesh back end
      {"cli/bench_solve.cpp", "emulator/cost_model.h"},
      {"solver/radiosity/cell_solver.cpp", "distributed/mpi_cell_ranks.h"},  // MPI in the core
      {"solver/radiosity/cell_ranks.h", "mpi.h"},
  };
  for (const auto& include : broken)
    EXPECT_EQ(layeringViolations({include}).size(), 1u) << include.file << " -> " << include.target;
  const std::vector<Include> fine = {
      {"solver/meshing/meshing.cpp", "solver/geometry/polygon_clip.h"},
      {"solver/backends/form_factor_backend.cpp", "solver/backends/mesh/mesh_backend.h"},
      {"solver/backends/mesh/mesh_backend.h", "emulator/mesh_machine.h"},
      {"emulator/mesh_machine.h", "parallel/thread_pool.h"},
      {"solver/backends/form_factor_backend.cpp", "solver/backends/native/native_backend.h"},
      {"viewer/solver_snapshot.h", "solver/backends/shot_stats.h"},
      {"bench/emulator_bench.cpp", "emulator/xnet.h"},  // shows the machine itself
      {"distributed/mpi_cell_ranks.h", "solver/radiosity/cell_ranks.h"},
      {"distributed/mesh_processes.cpp", "emulator/mpi/mpi_transport.h"},
  };
  for (const auto& include : fine)
    EXPECT_TRUE(layeringViolations({include}).empty()) << include.file << " -> " << include.target;
}

}  // namespace
}  // namespace radmesh
