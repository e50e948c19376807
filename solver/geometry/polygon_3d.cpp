#include "solver/geometry/polygon_3d.h"

#include <glm/glm.hpp>

namespace radmesh {

std::pair<int, int> dominantPlane(const Vec3& normal) {
  const Vec3 a = glm::abs(normal);
  const int drop = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
  return {(drop + 1) % 3, (drop + 2) % 3};
}

bool insidePolygon(const std::vector<Vec3>& vertices, const Vec3& normal, const Vec3& p) {
  const auto [u, v] = dominantPlane(normal);
  bool inside = false;  // crossing number of a ray along +u
  for (size_t i = 0, j = vertices.size() - 1; i < vertices.size(); j = i++) {
    const Vec3& a = vertices[i];
    const Vec3& b = vertices[j];
    if ((a[v] > p[v]) != (b[v] > p[v]) && p[u] < a[u] + (p[v] - a[v]) * (b[u] - a[u]) / (b[v] - a[v]))
      inside = !inside;
  }
  return inside;
}

}  // namespace radmesh
