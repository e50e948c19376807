// Host speed of the emulator's primitives on the MP-1's 64 x 64 grid, with the emulated MP-1
// seconds of one operation as a counter. Run: build-*/bench/emulator_bench
#include <benchmark/benchmark.h>

#include <random>

#include "emulator/cost_model.h"
#include "emulator/mesh_sort.h"
#include "emulator/reduce.h"
#include "emulator/router.h"
#include "emulator/scan.h"
#include "emulator/xnet.h"

namespace radmesh::emu {
namespace {

void reportEmulated(benchmark::State& state, const MeshMachine& machine) {
  state.counters["mp1_seconds_per_op"] =
      emulatedSeconds(machine.costs()).total() / static_cast<double>(state.iterations());
}

void BM_XnetShift(benchmark::State& state) {
  MeshMachine m;
  Plural<double> a(m, 1.0), b(m);
  for (auto _ : state) {
    xnetShift(m, b, a, Direction::SE, static_cast<int>(state.range(0)));
    benchmark::DoNotOptimize(b.data());
  }
  reportEmulated(state, m);
}
BENCHMARK(BM_XnetShift)->Arg(1)->Arg(5);

void BM_RouterSendAdd(benchmark::State& state) {
  MeshMachine m;
  Plural<double> v(m, 1.0), sum(m);
  Plural<int> to(m);
  std::mt19937 rng(1);
  std::uniform_int_distribution<int> pick(0, m.size() - 1);
  for (int pe = 0; pe < m.size(); ++pe) to[pe] = pick(rng);
  for (auto _ : state) {
    routerSend(m, sum, v, to, Combine::Add);
    benchmark::DoNotOptimize(sum.data());
  }
  reportEmulated(state, m);
}
BENCHMARK(BM_RouterSendAdd);

void BM_SegmentedScan(benchmark::State& state) {
  MeshMachine m;
  Plural<double> v(m, 1.0), out(m);
  Plural<bool> starts(m, false);
  for (int pe = 0; pe < m.size(); pe += 7) starts[pe] = true;
  for (auto _ : state) {
    segmentedScan(m, out, v, starts, ScanKind::Inclusive);
    benchmark::DoNotOptimize(out.data());
  }
  reportEmulated(state, m);
}
BENCHMARK(BM_SegmentedScan);

void BM_ReduceMax(benchmark::State& state) {
  MeshMachine m;
  Plural<double> v(m);
  for (int pe = 0; pe < m.size(); ++pe) v[pe] = (pe * 7919) % 4096;
  for (auto _ : state) benchmark::DoNotOptimize(reduceMax(m, v));
  reportEmulated(state, m);
}
BENCHMARK(BM_ReduceMax);

// k (key, value) pairs per PE: k = 4 is a 128 x 128 plane's pixels on 4096 PEs.
void BM_SortPairs(benchmark::State& state) {
  MeshMachine m;
  const int k = static_cast<int>(state.range(0));
  PeArray<int> keys(m, k, 0, "keys");
  PeArray<double> values(m, k, 0.0, "values");
  std::mt19937 rng(2);
  std::uniform_int_distribution<int> pick(0, 4000);
  for (auto _ : state) {
    state.PauseTiming();
    for (int pe = 0; pe < m.size(); ++pe)
      for (int s = 0; s < k; ++s) keys.at(pe, s) = pick(rng);
    state.ResumeTiming();
    sortPairs(m, keys, values);
  }
  reportEmulated(state, m);
}
BENCHMARK(BM_SortPairs)->Arg(1)->Arg(4)->Arg(16)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace radmesh::emu
