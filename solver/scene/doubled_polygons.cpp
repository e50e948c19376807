#include "solver/scene/doubled_polygons.h"

#include <algorithm>
#include <functional>
#include <utility>
#include <vector>

namespace radmesh {

namespace {

// The corners from the least (x, y, z) on, in the polygon's own order: the same for every listing
// of the same face from a different first corner.
std::vector<Vec3> canonicalCorners(const Polygon& p) {
  const auto less = [](const Vec3& a, const Vec3& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); };
  std::vector<Vec3> corners = p.vertices;
  std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end(), less), corners.end());
  return corners;
}

std::size_t hashOf(const std::vector<Vec3>& corners, int material) {
  std::size_t h = std::hash<int>{}(material);
  for (const Vec3& v : corners)
    for (double c : {v.x, v.y, v.z}) h = h * 1000003u ^ std::hash<double>{}(c);
  return h;
}

}  // namespace

DoubledPolygons dropDoubledPolygons(Scene& scene) {
  // Sorted by hash, then index: equal polygons sit together, the earliest first.
  std::vector<std::pair<std::size_t, std::size_t>> byHash;
  byHash.reserve(scene.polygons.size());
  for (std::size_t i = 0; i < scene.polygons.size(); ++i)
    byHash.emplace_back(hashOf(canonicalCorners(scene.polygons[i]), scene.polygons[i].material), i);
  std::sort(byHash.begin(), byHash.end());
  std::vector<char> doubled(scene.polygons.size(), 0);
  for (std::size_t a = 0; a < byHash.size(); ++a) {
    const std::size_t i = byHash[a].second;
    if (doubled[i]) continue;
    const std::vector<Vec3> corners = canonicalCorners(scene.polygons[i]);
    for (std::size_t b = a + 1; b < byHash.size() && byHash[b].first == byHash[a].first; ++b) {
      const Polygon& other = scene.polygons[byHash[b].second];
      if (other.material == scene.polygons[i].material && canonicalCorners(other) == corners)
        doubled[byHash[b].second] = 1;
    }
  }
  DoubledPolygons out;
  std::vector<Polygon> kept;
  kept.reserve(scene.polygons.size());
  for (std::size_t i = 0; i < scene.polygons.size(); ++i) {
    if (!doubled[i]) {
      kept.push_back(std::move(scene.polygons[i]));
      continue;
    }
    if (out.dropped++ == 0) out.first = polygonName(scene, i);
  }
  scene.polygons = std::move(kept);
  return out;
}

}  // namespace radmesh
