// One shot of the paper's algorithm on the built-in office, native and emulated mesh side by side
// in one run, at 64^2 and 128^2 (the viewer's rates) and 256^2; for the mesh: the emulated MP-1
// seconds per iteration, the depths at (a) and (b), and where the emulator's host time goes: by
// phase ("ms phase ...") and by operation class ("ms op ...", with "ms op between" the host work
// between the machine's operations). Run: build/bench/mesh_backend_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <numeric>
#include <string>
#include <utility>

#include "solver/backends/form_factor_backend.h"
#include "solver/io/builtin_scenes.h"
#include "solver/meshing/meshing.h"

namespace radmesh {
namespace {

// Every benchmark shoots the same shooters once each, so the emulated figures are reproducible.
constexpr std::size_t kShots = 40;

struct Office {
  Scene scene = builtinScene("office");
  std::vector<Patch> patches = meshScene(scene);
  std::vector<int> shooters;  // up to half emitters, strongest first, then patches across the room
  Office() {
    std::vector<int> order(patches.size());
    std::iota(order.begin(), order.end(), 0);
    auto power = [&](int j) {
      const Rgb e = scene.materials[patches[j].material].emittance;
      return (e.r + e.g + e.b) * patches[j].areaM2;
    };
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return power(a) > power(b); });
    for (int j : order)
      if (power(j) > 0.0 && shooters.size() < kShots / 2) shooters.push_back(j);
    for (std::size_t k = 0; shooters.size() < kShots; ++k) shooters.push_back(static_cast<int>(k * 7919 % patches.size()));
  }
};

const Office& office() {
  static const Office o;
  return o;
}

// Shoots the office's shooters in turn; on a back end with a machine of its own (the mesh),
// reports from its shot figures the machine seconds, the depths and where the host time goes.
void shoot(benchmark::State& state, FormFactorBackend& backend) {
  const Office& o = office();
  std::vector<FormFactorRow> rows;
  std::size_t next = 0;
  double machine = 0.0, depthA = 0.0, depthB = 0.0;
  std::map<std::string, double> host;  // counter name -> host seconds over the shots
  bool figures = false;
  for (auto _ : state) {
    const int shooter[] = {o.shooters[next++ % o.shooters.size()]};
    const auto start = std::chrono::steady_clock::now();
    backend.computeRows(shooter, rows);
    const std::shared_ptr<const ShotStats> s = backend.lastShotStats();
    if (!s) continue;
    figures = true;
    const nlohmann::json& f = s->figures;
    const double shotHost = f.at("host_seconds").get<double>();
    // After the shot the host assembles the rows (and refines sub-pixel receivers).
    host["ms rows on host"] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() - shotHost;
    machine += s->machineSeconds;
    depthA += f.at("depth_a_max").get<double>();
    depthB += f.at("depth_b_max").get<double>();
    for (const auto& p : f.at("phases")) host["ms phase " + p.at("name").get<std::string>()] += p.at("host_seconds").get<double>();
    double inOperations = 0.0;
    for (const char* name : {"xnet", "router", "alu", "reduce", "scan", "sort"}) {
      const double seconds = f.at("op_counts").at(name).at("host_seconds").get<double>();
      host[std::string("ms op ") + name] += seconds;
      inOperations += seconds;
    }
    host["ms op between"] += shotHost - inOperations;
  }
  state.counters["iterations_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  if (!figures) return;
  const double n = static_cast<double>(state.iterations());
  state.counters["mp1_s_per_it"] = machine / n;
  state.counters["depth_a_max"] = depthA / n;
  state.counters["depth_b_max"] = depthB / n;
  for (const auto& [name, seconds] : host) state.counters[name] = seconds / n * 1e3;
}

SolveOptions optionsOf(int resolution, int threads) {
  SolveOptions options;
  options.resolution = resolution;
  options.threads = threads;
  return options;
}

// {backend (0 native, 1 mesh), resolution, host threads}: the two back ends side by side.
void BM_Shot(benchmark::State& state) {
  const Office& o = office();
  SolveOptions options = optionsOf(static_cast<int>(state.range(1)), static_cast<int>(state.range(2)));
  options.backend = state.range(0) == 1 ? Backend::Mesh : Backend::Native;
  const auto backend = makeFormFactorBackend(o.scene, o.patches, options);
  state.SetLabel(toString(options.backend));
  shoot(state, *backend);
}
BENCHMARK(BM_Shot)
    ->ArgsProduct({{0, 1}, {64, 128, 256}, {1, 2}})
    ->Iterations(kShots)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// {mapping (0 hierarchical, 1 cut-and-stack, 2 adaptive), resolution}: the mesh back end, 2 threads.
void BM_Mapping(benchmark::State& state) {
  const Office& o = office();
  const MappingKind kinds[] = {MappingKind::Hierarchical, MappingKind::CutAndStack, MappingKind::Adaptive};
  SolveOptions options = optionsOf(static_cast<int>(state.range(1)), 2);
  options.backend = Backend::Mesh;
  options.mapping = kinds[state.range(0)];
  const auto backend = makeFormFactorBackend(o.scene, o.patches, options);
  state.SetLabel(toString(options.mapping));
  shoot(state, *backend);
}
BENCHMARK(BM_Mapping)
    ->ArgsProduct({{0, 1, 2}, {64, 128, 256}})
    ->Iterations(kShots)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace radmesh
