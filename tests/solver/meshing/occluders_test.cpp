// The occluders' hierarchy (solver/meshing/occluders.h) against the definition it speeds up: a
// segment is blocked where it crosses a patch of any polygon but the two it joins.
#include "solver/meshing/occluders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "solver/io/builtin_scenes.h"
#include "solver/meshing/meshing.h"
#include "tests/solver/patch_fixtures.h"

namespace radmesh::test {
namespace {

// A linear congruential generator in [0, 1), the same on every platform.
struct Uniform {
  unsigned state;
  double operator()() {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / static_cast<double>(1u << 24);
  }
};

// A point on patch p, its centroid where (u, v) falls outside the triangle of its first corners.
Vec3 pointOn(const Patch& p, double u, double v) {
  const Vec3 a = p.vertices[0], b = p.vertices[1], c = p.vertices[p.vertexCount - 1];
  return u + v <= 1.0 ? a + u * (b - a) + v * (c - a) : p.centroid;
}

// Segments between random points of random patches; the number the hierarchy calls blocked, each
// asserted equal to testing every patch.
int blockedSegments(const std::vector<Patch>& patches, int segments, unsigned seed) {
  const Occluders occluders(patches);
  Uniform next{seed};
  int blocked = 0;
  for (int i = 0; i < segments; ++i) {
    const Patch& from = patches[static_cast<size_t>(next() * patches.size()) % patches.size()];
    const Patch& to = patches[static_cast<size_t>(next() * patches.size()) % patches.size()];
    const Vec3 a = pointOn(from, 0.5 * next(), 0.5 * next()), b = pointOn(to, 0.5 * next(), 0.5 * next());
    const bool everyPatch = std::ranges::any_of(patches, [&](const Patch& p) {
      return p.polygon != from.polygon && p.polygon != to.polygon && segmentCrosses(a, b, p);
    });
    EXPECT_EQ(occluders.segmentBlocked(a, b, from.polygon, to.polygon), everyPatch) << "segment " << i;
    if (::testing::Test::HasFailure()) return blocked;
    blocked += everyPatch;
  }
  return blocked;
}

TEST(Occluders, AnswerAsTestingEveryPatchOnTheOffice) {
  // Walls and a floor of many patches each beside furniture of many small polygons.
  const std::vector<Patch> patches = meshScene(builtinScene("office"), 0.75);
  constexpr int kSegments = 4000;
  const int blocked = blockedSegments(patches, kSegments, 12345u);
  // Both answers are common: a hierarchy that always says one of them fails.
  EXPECT_GT(blocked, kSegments / 10);
  EXPECT_LT(blocked, kSegments - kSegments / 10);
}

TEST(Occluders, AnswerAsTestingEveryPatchOnARowOfSquaresEachLargerThanTheLast) {
  // 300 squares facing +y, each twice as wide and twice as far as the one before: the splitting
  // heuristic peels them off a few at a time, 89 levels deep, past the traversal's stack, were its
  // depth not bounded (a sanitizer build reports the overrun).
  constexpr int kSquares = 300;
  std::vector<Patch> patches;
  for (int k = 0; k < kSquares; ++k) {
    const double h = 0.5 * std::pow(2.0, k), y = std::pow(2.0, k);
    patches.push_back(makePatch({{-h, y, -h}, {-h, y, h}, {h, y, h}, {h, y, -h}}, 0, k));
  }
  constexpr int kSegments = 2000;
  const int blocked = blockedSegments(patches, kSegments, 777u);
  EXPECT_GT(blocked, kSegments / 10);
  EXPECT_LT(blocked, kSegments);  // squares side by side see each other
}

}  // namespace
}  // namespace radmesh::test
