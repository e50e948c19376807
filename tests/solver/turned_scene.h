#pragma once
// Scenes turned about the vertical (z): buildings are rarely drawn along the world axes.
#include <cmath>
#include <numbers>

#include "solver/scene/scene.h"

namespace radmesh::test {

inline Vec3 turnedAboutVertical(const Vec3& v, double degrees) {
  const double a = degrees * std::numbers::pi / 180.0;
  return {std::cos(a) * v.x - std::sin(a) * v.y, std::sin(a) * v.x + std::cos(a) * v.y, v.z};
}

inline void turnAboutVertical(Scene& scene, double degrees) {
  for (Polygon& polygon : scene.polygons)
    for (Vec3& v : polygon.vertices) v = turnedAboutVertical(v, degrees);
}

}  // namespace radmesh::test
