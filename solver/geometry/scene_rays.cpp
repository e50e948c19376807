#include "solver/geometry/scene_rays.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "solver/geometry/polygon_3d.h"

namespace radmesh {

SceneRays::SceneRays(const Scene& scene) : scene_(scene), lo_(std::numeric_limits<double>::infinity()),
                                            hi_(-std::numeric_limits<double>::infinity()),
                                            bucket_(std::max(sceneDiagonal(scene) / 64.0, 1e-9)), grid_(bucket_) {
  normals_.reserve(scene.polygons.size());
  for (size_t i = 0; i < scene.polygons.size(); ++i) {
    const std::vector<Vec3>& v = scene.polygons[i].vertices;
    const auto [lo, hi] = boundingBox(v);
    // A polygon across much of the scene would fill thousands of buckets: every ray tests it instead.
    const Vec3 span = glm::floor(hi / bucket_) - glm::floor(lo / bucket_) + 1.0;
    if (span.x * span.y * span.z > 4096.0)
      large_.push_back(static_cast<int>(i));
    else
      grid_.insert(lo, hi, static_cast<int>(i));
    normals_.push_back(newellNormal(v));
    lo_ = glm::min(lo_, lo - bucket_), hi_ = glm::max(hi_, hi + bucket_);
  }
}

bool SceneRays::hits(const Vec3& origin, const Vec3& direction, double fromM, int skip) const {
  // The stretch of the ray inside the polygons' box (slabs); none outside it can meet one.
  double near = 0.0, far = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (std::abs(direction[k]) < 1e-300) {
      if (origin[k] < lo_[k] || origin[k] > hi_[k]) return false;
      continue;
    }
    const double a = (lo_[k] - origin[k]) / direction[k], b = (hi_[k] - origin[k]) / direction[k];
    near = std::max(near, std::min(a, b)), far = std::min(far, std::max(a, b));
  }
  const auto meets = [&](int i) {
    if (i == skip) return false;
    const Polygon& p = scene_.polygons[i];
    const Vec3& n = normals_[i];
    const double along = glm::dot(direction, n);
    if (std::abs(along) <= 1e-12 * glm::length(n)) return false;  // parallel to its plane
    const double t = glm::dot(p.vertices[0] - origin, n) / along;
    return t > fromM && insidePolygon(p.vertices, n, origin + t * direction);
  };
  if (std::any_of(large_.begin(), large_.end(), meets)) return true;
  for (double t = near; t < far; t += bucket_) {
    const Vec3 a = origin + t * direction, b = origin + std::min(t + bucket_, far) * direction;
    if (grid_.anyInBox(glm::min(a, b), glm::max(a, b), meets)) return true;
  }
  return false;
}

bool lightCanLeave(const Scene& scene, const std::vector<BoundarySegment>& open) {
  // A Fibonacci sphere turned off the axes, so that no ray runs along a seam of an axis-aligned model.
  constexpr int kRays = 32;
  std::array<Vec3, kRays> directions;
  for (int i = 0; i < kRays; ++i) {
    const double z = 1.0 - (i + 0.5) * 2.0 / kRays, r = std::sqrt(1.0 - z * z);
    const double phi = 0.1234 + i * std::numbers::pi * (3.0 - std::sqrt(5.0));
    directions[i] = Vec3(r * std::cos(phi), r * std::sin(phi), z);
  }
  const SceneRays rays(scene);
  const double clearance = 1e-7 * sceneDiagonal(scene);
  for (const BoundarySegment& s : open)
    for (const Vec3& d : directions)
      if (!rays.hits(0.5 * (s.a + s.b), d, clearance)) return true;
  // Faces that look out of the model (a solid's outside, a light facing away): four directions of
  // each one's front, a different four for each, from a point inside it. A face lying on it (a
  // chair leg's foot on the floor) covers it, so faces through the point count.
  for (size_t i = 0; i < scene.polygons.size(); ++i) {
    const std::vector<Vec3>& v = scene.polygons[i].vertices;
    const Vec3 n = newellNormal(v);
    if (n == Vec3(0.0)) continue;  // no area, no front
    for (size_t k = 1; k + 1 < v.size(); ++k) {
      const Vec3 inside = (v[0] + v[k] + v[k + 1]) / 3.0;
      if (!insidePolygon(v, n, inside)) continue;
      for (size_t j = 0; j < 4; ++j) {
        const Vec3& d = directions[(7 * i + 8 * j) % kRays];
        if (!rays.hits(inside, glm::dot(d, n) < 0.0 ? -d : d, -clearance, static_cast<int>(i))) return true;
      }
      break;
    }
  }
  return false;
}

}  // namespace radmesh
