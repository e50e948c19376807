// What each skip of the effects plan saves: every skip against --effects all on a scene built for
// it, side by side (solver/radiosity/effects_plan.h). One benchmark = meshing excluded, one whole solve.
// Run: build/bench/effects_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <functional>
#include <string>

#include "solver/meshing/meshing.h"
#include "solver/radiosity/progressive_solver.h"

namespace radmesh {
namespace {

// An axis-aligned cube [corner, corner + size]: faces inward (a room) or outward (a block).
void addCube(Scene& scene, Vec3 corner, double size, bool inward, int material) {
  const Vec3 c[8] = {corner + Vec3(0, 0, 0), corner + Vec3(size, 0, 0), corner + Vec3(size, size, 0),
                     corner + Vec3(0, size, 0), corner + Vec3(0, 0, size), corner + Vec3(size, 0, size),
                     corner + Vec3(size, size, size), corner + Vec3(0, size, size)};
  const int outward[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  for (const auto& f : outward) {
    Polygon p;
    p.material = material;
    for (int k = 0; k < 4; ++k) p.vertices.push_back(c[f[inward ? 3 - k : k]]);
    scene.polygons.push_back(p);
  }
}

// A closed unit room lit by its whole ceiling; `block` adds a cube on the floor that hides
// patches from one another (occlusion on).
Scene room(Rgb wall, bool block) {
  Scene s;
  s.source = "bench room";
  s.materials = {{"wall", wall, Rgb(0.0)}, {"light", Rgb(0.0), Rgb(10.0)}};
  addCube(s, Vec3(0.0), 1.0, true, 0);
  s.polygons[1].material = 1;  // the ceiling
  if (block) addCube(s, Vec3(0.3, 0.3, 0.0), 0.35, false, 0);
  return s;
}

// Small squares on a 4 x 4 x 4 lattice 1 m apart, lit by one of them: nothing near anything.
Scene separatedSquares() {
  Scene s;
  s.source = "separated squares";
  s.materials = {{"grey", Rgb(0.5, 0.4, 0.3), Rgb(0.0)}, {"light", Rgb(0.0), Rgb(10.0)}};
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 4; ++y)
      for (int z = 0; z < 4; ++z) {
        const Vec3 o(x, y, z);
        const double a = 0.1;
        const bool up = (x + y + z) % 2 == 0;  // alternate facing so that squares see one another
        s.polygons.push_back(up ? Polygon{{o, o + Vec3(a, 0, 0), o + Vec3(a, a, 0), o + Vec3(0, a, 0)}, 0, ""}
                                : Polygon{{o, o + Vec3(0, a, 0), o + Vec3(a, a, 0), o + Vec3(a, 0, 0)}, 0, ""});
      }
  s.polygons.front().material = 1;
  return s;
}

struct Scenario {
  const char* skip;  // the effect the scene lets auto skip
  std::function<Scene()> scene;
  double cellM;
  std::size_t cacheBytes;  // a row cache makes later iterations update-bound (colour)
  double until;
};

const Scenario kScenarios[] = {
    {"occlusion", [] { return room(Rgb(0.7, 0.5, 0.3), false); }, 0.1, 0, 0.95},
    {"colour", [] { return room(Rgb(0.6), true); }, 0.1, std::size_t(1) << 30, 0.999},
    {"interreflection", [] { return room(Rgb(0.0), true); }, 0.1, 0, 0.95},
    {"near field", separatedSquares, 0.2, 0, 0.95},
    {"escape", [] { return room(Rgb(0.7, 0.5, 0.3), true); }, 0.1, 0, 0.95},
};

void BM_Solve(benchmark::State& state, const Scenario& scenario, EffectsMode mode) {
  const Scene scene = scenario.scene();
  const std::vector<Patch> patches = meshScene(scene, scenario.cellM);
  SolveOptions o;
  o.projection = Projection::Plane;
  o.resolution = 128;
  o.threads = 1;
  o.until = scenario.until;
  o.formFactorCacheBytes = scenario.cacheBytes;
  o.effects = mode;
  size_t iterations = 0;
  bool skipped = false;
  for (auto _ : state) {
    ProgressiveSolver solver(scene, patches, o);
    while (!solver.done()) solver.step();
    iterations = solver.history().size();
    for (const Effect& e : solver.effectsPlan().effects) skipped |= e.name == scenario.skip && !e.on;
    benchmark::DoNotOptimize(solver.radiosity().data());
  }
  state.counters["patches"] = static_cast<double>(patches.size());
  state.counters["iterations"] = static_cast<double>(iterations);
  state.counters["skipped"] = skipped;
}

const bool kRegistered = [] {
  for (const Scenario& s : kScenarios)
    for (EffectsMode mode : {EffectsMode::Auto, EffectsMode::All})
      benchmark::RegisterBenchmark((std::string("BM_Solve/") + s.skip + "/" + toString(mode)).c_str(), BM_Solve, s, mode)
          ->Unit(benchmark::kMillisecond);
  return true;
}();

}  // namespace
}  // namespace radmesh
