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

#include "solver/io/builtin_scenes.h"
#include "solver/backends/mesh/mesh_backend.h"
#include "solver/meshing/meshing.h"
#include "solver/backends/native/native_backend.h"

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

// Shoots the office's shooters in turn; for the mesh, reports the emulated cost and depths.
void shoot(benchmark::State& state, FormFactorBackend& backend, const MeshBackend* mesh) {
  const Office& o = office();
  std::vector<FormFactorRow> rows;
  std::size_t next = 0;
  double emulated = 0.0, depthA = 0.0, depthB = 0.0;
  std::map<std::string, double> host;  // counter name -> host seconds over the shots
  for (auto _ : state) {
    const int shooter[] = {o.shooters[next++ % o.shooters.size()]};
    const auto start = std::chrono::steady_clock::now();
    backend.computeRows(shooter, rows);
    if (!mesh) continue;
    const MeshShotStats& s = mesh->lastShot();
    // After the shot the host assembles the rows (and refines sub-pixel receivers).
    host["ms rows on host"] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() - s.hostSeconds;
    emulated += s.emulatedSeconds;
    depthA += s.depthAMax;
    depthB += s.depthBMax;
    for (const MeshPhaseCost& p : s.phases) host["ms phase " + p.name] += p.hostSeconds;
    const std::pair<const char*, const emu::ClassCounts&> classes[] = {
        {"xnet", s.counts.xnet},     {"router", s.counts.router}, {"alu", s.counts.alu},
        {"reduce", s.counts.reduce}, {"scan", s.counts.scan},     {"sort", s.counts.sort}};
    double inOperations = 0.0;
    for (const auto& [name, counts] : classes) {
      host[std::string("ms op ") + name] += counts.hostSeconds;
      inOperations += counts.hostSeconds;
    }
    host["ms op between"] += s.hostSeconds - inOperations;
  }
  state.counters["iterations_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  if (!mesh) return;
  const double n = static_cast<double>(state.iterations());
  state.counters["mp1_s_per_it"] = emulated / n;
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
  const SolveOptions options = optionsOf(static_cast<int>(state.range(1)), static_cast<int>(state.range(2)));
  if (state.range(0) == 1) {
    MeshBackend mesh(o.scene, o.patches, options);
    state.SetLabel("mesh");
    shoot(state, mesh, &mesh);
  } else {
    NativeBackend native(o.scene, o.patches, options);
    state.SetLabel("native");
    shoot(state, native, nullptr);
  }
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
  MeshBackendOptions mapping;
  mapping.mapping = kinds[state.range(0)];
  MeshBackend mesh(o.scene, o.patches, optionsOf(static_cast<int>(state.range(1)), 2), mapping);
  state.SetLabel(toString(mapping.mapping));
  shoot(state, mesh, &mesh);
}
BENCHMARK(BM_Mapping)
    ->ArgsProduct({{0, 1, 2}, {64, 128, 256}})
    ->Iterations(kShots)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace radmesh
