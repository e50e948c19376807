// Ear clipping of large concave faces: a star outline (radii alternating 5 and 4.6 m) of 1 000 to
// 100 000 vertices, as CAD exports of curved walls and site outlines give. Its tips are ears at
// once; the convex remainder is then clipped in a fan whose ears span it, which a scan of every
// corner per ear made quadratic.
// Run: build/bench/geometry_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <vector>

#include "solver/geometry/polygon_triangulate.h"
#include "tests/solver/geometry/star_outline.h"

namespace radmesh {
namespace {

void BM_TriangulateStar(benchmark::State& state) {
  const std::vector<Vec2> outline = starOutline(static_cast<int>(state.range(0)), 5.0, 4.6);
  size_t triangles = 0;
  for (auto _ : state) triangles = triangulatePolygon(outline, 1e-12 * extentOf(outline)).size();
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(BM_TriangulateStar)->ArgName("vertices")->Arg(1000)->Arg(10000)->Arg(30000)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace radmesh
