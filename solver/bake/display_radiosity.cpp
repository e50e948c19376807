#include "solver/bake/display_radiosity.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace radmesh {

namespace {

// Finds the vertex a patch corner welds to: one within `toleranceM` of it (looked up in a hash of
// quantised positions, the neighbouring buckets included so that a bucket boundary cannot split
// two coincident corners) with the same material and the same normal.
//
// Corners are welded only where patches share them as corners. Across two polygons, a corner of
// one that lies inside an edge of the other (a T-junction: the polygons' own corners need not be
// on the grid) gets no weight from the other side, so shading may step slightly along that edge.
class Welder {
 public:
  explicit Welder(double toleranceM) : tolerance_(toleranceM) {}

  int find(const DisplayMesh& mesh, const std::vector<int>& materialOf, const Vec3& position,
           const Vec3& normal, int material) const {
    const Key home = keyOf(position);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto bucket = buckets_.find(Key{home.x + dx, home.y + dy, home.z + dz});
          if (bucket == buckets_.end()) continue;
          for (int vertex : bucket->second)
            if (materialOf[vertex] == material && glm::dot(mesh.normals[vertex], normal) > 1.0 - 1e-9 &&
                glm::length(mesh.positions[vertex] - position) <= tolerance_)
              return vertex;
        }
    return -1;
  }

  void insert(const Vec3& position, int vertex) { buckets_[keyOf(position)].push_back(vertex); }

 private:
  struct Key {
    std::int64_t x, y, z;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    size_t operator()(const Key& k) const {
      // Unsigned: the mixing is meant to wrap around.
      const auto u = [](std::int64_t x) { return static_cast<std::uint64_t>(x); };
      return std::hash<std::uint64_t>()(u(k.x) * 73856093u ^ u(k.y) * 19349663u ^ u(k.z) * 83492791u);
    }
  };
  Key keyOf(const Vec3& p) const {
    const Vec3 q = glm::floor(p / tolerance_);
    return {static_cast<std::int64_t>(q.x), static_cast<std::int64_t>(q.y), static_cast<std::int64_t>(q.z)};
  }

  double tolerance_;
  std::unordered_map<Key, std::vector<int>, KeyHash> buckets_;
};

// Coincidence tolerance: far below any patch (a billionth of the scene's size), far above the
// rounding of grid points computed from different polygons.
double weldTolerance(const std::vector<Patch>& patches) {
  Vec3 lo = patches[0].vertices[0], hi = lo;
  for (const Patch& p : patches)
    for (int i = 0; i < p.vertexCount; ++i) {
      lo = glm::min(lo, p.vertices[i]);
      hi = glm::max(hi, p.vertices[i]);
    }
  const double magnitude = std::max(glm::length(lo), glm::length(hi));
  return std::max(1e-9 * glm::length(hi - lo), 1e-14 * magnitude) + 1e-300;
}

}  // namespace

DisplayMesh buildDisplayMesh(const std::vector<Patch>& patches) {
  DisplayMesh mesh;
  if (patches.empty()) return mesh;
  Welder welder(weldTolerance(patches));
  std::vector<int> materialOf;  // per vertex
  for (size_t p = 0; p < patches.size(); ++p) {
    const Patch& patch = patches[p];
    std::array<unsigned, 4> corner{};
    for (int i = 0; i < patch.vertexCount; ++i) {
      int vertex = welder.find(mesh, materialOf, patch.vertices[i], patch.normal, patch.material);
      if (vertex < 0) {
        vertex = static_cast<int>(mesh.positions.size());
        mesh.positions.push_back(patch.vertices[i]);
        mesh.normals.push_back(patch.normal);
        mesh.vertexSources.emplace_back();
        materialOf.push_back(patch.material);
        welder.insert(patch.vertices[i], vertex);
      }
      // Area weight: a large patch speaks for more of the surface around the vertex.
      mesh.vertexSources[vertex].emplace_back(static_cast<int>(p), patch.areaM2);
      corner[i] = static_cast<unsigned>(vertex);
    }
    // A convex quad splits along either diagonal; (0, 2) keeps both triangles counter-clockwise.
    for (int t = 0; t + 2 < patch.vertexCount; ++t) {
      mesh.indices.insert(mesh.indices.end(), {corner[0], corner[t + 1], corner[t + 2]});
      mesh.patchOfTriangle.push_back(static_cast<int>(p));
    }
  }
  return mesh;
}

std::vector<Rgb> vertexRadiosity(const DisplayMesh& mesh, const std::vector<Rgb>& patchRadiosity) {
  std::vector<Rgb> out(mesh.positions.size(), Rgb(0.0));
  for (size_t v = 0; v < mesh.vertexSources.size(); ++v) {
    double weight = 0.0;
    for (const auto& [patch, areaM2] : mesh.vertexSources[v]) {
      if (patch < 0 || static_cast<size_t>(patch) >= patchRadiosity.size())
        throw std::invalid_argument("vertexRadiosity: patch " + std::to_string(patch) +
                                    " has no radiosity (" + std::to_string(patchRadiosity.size()) +
                                    " given)");
      out[v] += areaM2 * patchRadiosity[patch];
      weight += areaM2;
    }
    if (weight > 0.0) out[v] /= weight;
  }
  return out;
}

}  // namespace radmesh
