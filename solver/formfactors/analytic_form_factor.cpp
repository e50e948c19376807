#include "solver/formfactors/analytic_form_factor.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <numbers>

namespace radmesh {

double pointToPolygonFormFactor(std::span<const Vec3> vertices) {
  // Clip to z >= 0; a convex polygon of n vertices keeps at most n + 1.
  std::array<Vec3, 16> clipped;
  int count = 0;
  const size_t n = vertices.size();
  assert(n < clipped.size());  // patches have 3 or 4 vertices
  for (size_t k = 0; k < n; ++k) {
    const Vec3& p = vertices[k];
    const Vec3& q = vertices[(k + 1) % n];
    if (p.z >= 0.0) clipped[count++] = p;
    if ((p.z >= 0.0) != (q.z >= 0.0)) {
      Vec3 crossing = p + (p.z / (p.z - q.z)) * (q - p);
      crossing.z = 0.0;
      clipped[count++] = crossing;
    }
  }
  if (count < 3) return 0.0;

  // F = 1/(2 pi) sum over edges of (angle the edge subtends) x (cosine between the normal of the
  // plane through the origin and the edge, and the z axis).
  double sum = 0.0;
  for (int k = 0; k < count; ++k) {
    const Vec3& a = clipped[k];
    const Vec3& b = clipped[(k + 1) % count];
    const Vec3 c = glm::cross(a, b);
    const double length = glm::length(c);
    if (!(length > 0.0)) continue;  // an edge through the origin or of no length subtends nothing
    sum += std::atan2(length, glm::dot(a, b)) * c.z / length;
  }
  return std::abs(sum) / (2.0 * std::numbers::pi);
}

double smallPolygonFormFactor(std::span<const Vec3> vertices, Vec3 centroid, Vec3 normal, double areaM2) {
  const double r2 = glm::dot(centroid, centroid);
  const bool inFront = std::all_of(vertices.begin(), vertices.end(), [](const Vec3& v) { return v.z > 0.0; });
  if (!inFront || !(squaredDiameter(vertices) <= kSmallPolygonRatio * kSmallPolygonRatio * r2))
    return pointToPolygonFormFactor(vertices);
  return differentialFormFactor(centroid, normal, areaM2);
}

double squaredDiameter(std::span<const Vec3> vertices) {
  double diameter2 = 0.0;
  for (size_t k = 0; k < vertices.size(); ++k)
    for (size_t m = k + 1; m < vertices.size(); ++m) {
      const Vec3 d = vertices[k] - vertices[m];
      diameter2 = std::max(diameter2, glm::dot(d, d));
    }
  return diameter2;
}

double differentialFormFactor(Vec3 centroid, Vec3 normal, double areaM2) {
  const double r2 = glm::dot(centroid, centroid);
  const double cosHere = centroid.z, cosThere = std::abs(glm::dot(normal, centroid));  // each times r
  return cosHere * cosThere * areaM2 / (std::numbers::pi * r2 * r2);
}

}  // namespace radmesh
