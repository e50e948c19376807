#include "solver/formfactors/analytic_form_factor.h"

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

}  // namespace radmesh
