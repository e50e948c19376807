#pragma once
// A star outline, counter-clockwise, its vertices alternating between two radii: its tips are ears
// at once, and the convex remainder is then clipped in a fan whose ears span it. The ear clipper's
// test (polygon_triangulate_test.cpp) and benchmark (bench/geometry_bench.cpp) both use it.
#include <cmath>
#include <numbers>
#include <vector>

#include "solver/geometry/polygon_2d.h"

namespace radmesh {

inline std::vector<Vec2> starOutline(int vertices, double outerRadius, double innerRadius) {
  std::vector<Vec2> outline;
  for (int k = 0; k < vertices; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / vertices, radius = k % 2 ? innerRadius : outerRadius;
    outline.push_back({radius * std::cos(angle), radius * std::sin(angle)});
  }
  return outline;
}

}  // namespace radmesh
