// Time per iteration of the native solver (plane and hemicube, 64^2 .. 512^2) on the built-in
// office meshed at the paper's 15-inch grid, time to the paper's 95 %, and scaling with patch count.
// Run: build-solver/bench/solver_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <map>
#include <memory>

#include "solver/io/builtin_scenes.h"
#include "solver/meshing/meshing.h"
#include "solver/radiosity/progressive_solver.h"

namespace radmesh {
namespace {

struct Meshed {
  Scene scene;
  std::vector<Patch> patches;
};

const Meshed& office(double cellM) {
  static std::map<double, std::unique_ptr<Meshed>> cache;
  auto& slot = cache[cellM];
  if (!slot) {
    slot = std::make_unique<Meshed>();
    slot->scene = builtinScene("office");
    slot->patches = meshScene(slot->scene, cellM);
  }
  return *slot;
}

SolveOptions options(const benchmark::State& state) {
  SolveOptions o;
  o.projection = state.range(0) == 0 ? Projection::Plane : Projection::Hemicube;
  o.resolution = static_cast<int>(state.range(1));
  o.threads = static_cast<int>(state.range(2));
  o.until = 1.0;  // never stop on convergence: every step is a full iteration
  return o;
}

// One step = pick the shooter, project every patch, z-buffer, sum delta form factors, update B.
void BM_Iteration(benchmark::State& state) {
  const Meshed& m = office(kDefaultCellM);
  ProgressiveSolver solver(m.scene, m.patches, options(state));
  for (auto _ : state) benchmark::DoNotOptimize(solver.step());
  state.counters["patches"] = static_cast<double>(m.patches.size());
}
BENCHMARK(BM_Iteration)
    ->ArgNames({"hemicube", "N", "threads"})
    ->ArgsProduct({{0, 1}, {64, 128, 256, 512}, {1}})
    ->Args({0, 256, 2})
    ->Args({1, 256, 2})
    ->Unit(benchmark::kMillisecond);

// From the first shot to C = 0.95, as in the paper's Figure 1.3.
void BM_TimeTo95(benchmark::State& state) {
  const Meshed& m = office(kDefaultCellM);
  SolveOptions o = options(state);
  o.until = 0.95;
  int iterations = 0;
  for (auto _ : state) {
    ProgressiveSolver solver(m.scene, m.patches, o);
    while (!solver.done()) solver.step();
    iterations = static_cast<int>(solver.history().size());
  }
  state.counters["iterations"] = iterations;
  state.counters["patches"] = static_cast<double>(m.patches.size());
}
BENCHMARK(BM_TimeTo95)
    ->ArgNames({"hemicube", "N", "threads"})
    ->Args({0, 256, 1})
    ->Args({0, 256, 2})
    ->Args({1, 256, 1})
    ->Unit(benchmark::kMillisecond);

// Per-iteration cost against patch count: the office meshed at cells from 0.6 m down to 0.1 m.
void BM_PatchScaling(benchmark::State& state) {
  const Meshed& m = office(static_cast<double>(state.range(3)) / 1000.0);
  ProgressiveSolver solver(m.scene, m.patches, options(state));
  for (auto _ : state) benchmark::DoNotOptimize(solver.step());
  state.counters["patches"] = static_cast<double>(m.patches.size());
}
BENCHMARK(BM_PatchScaling)
    ->ArgNames({"hemicube", "N", "threads", "cell_mm"})
    ->ArgsProduct({{0}, {256}, {1}, {600, 381, 200, 100}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace radmesh
