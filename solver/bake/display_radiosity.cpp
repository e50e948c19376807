#include "solver/bake/display_radiosity.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <span>
#include <utility>

#include "solver/geometry/point_grid.h"
#include "solver/bake/t_vertices.h"

namespace radmesh {

namespace {

using Sources = std::vector<std::pair<int, double>>;  // DisplayMesh::vertexSources of one vertex

// Corners within `toleranceM` of one another are one point, at the first one's position, so that
// the edges of different smoothing groups meet exactly (a hairline between a table's top and its
// sides shows the inside of the table).
class Points {
 public:
  // Buckets far wider than the tolerance: a look-up mostly meets one.
  explicit Points(double toleranceM) : tolerance_(toleranceM), grid_(64.0 * toleranceM) {}

  int indexOf(const Vec3& position) {
    int found = -1;
    grid_.anyInBox(position - Vec3(tolerance_), position + Vec3(tolerance_), [&](int point) {
      if (glm::length(positions_[point] - position) <= tolerance_) found = point;
      return found >= 0;
    });
    if (found < 0) {
      found = static_cast<int>(positions_.size());
      positions_.push_back(position);
      grid_.insert(position, found);
    }
    return found;
  }
  const std::vector<Vec3>& positions() const { return positions_; }

 private:
  double tolerance_;
  PointGrid grid_;
  std::vector<Vec3> positions_;
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

// The sources of a point at t along the edge from a vertex to another: (1 - t) B(from) + t B(to),
// as weights of patches (each end's weights scaled to sum to its share).
Sources alongEdge(const Sources& from, const Sources& to, double t) {
  Sources out;
  auto add = [&](const Sources& end, double share) {
    double total = 0.0;
    for (const auto& [patch, weight] : end) total += weight;
    if (total > 0.0)
      for (const auto& [patch, weight] : end) out.emplace_back(patch, share * weight / total);
  };
  add(from, 1.0 - t);
  add(to, t);
  // One entry per patch: a patch that touches both ends (the usual case) once.
  std::sort(out.begin(), out.end());
  size_t kept = 0;
  for (size_t i = 0; i < out.size(); ++i)
    if (kept > 0 && out[kept - 1].first == out[i].first)
      out[kept - 1].second += out[i].second;
    else
      out[kept++] = out[i];
  out.resize(kept);
  return out;
}

// Whether a patch standing at the point (its corner or edge there, in another plane, on the side a
// and b face) has a and b on opposite sides: a wall of no thickness on the seam of two floors, or a
// cabinet's side, which must not be averaged across (the dark side would take the lit one's light).
// A window's reveal, behind the wall it cuts, stands on nothing.
bool separatedAt(const std::vector<int>& touching, const Patch& a, const Patch& b, const std::vector<Patch>& patches,
                 double toleranceM) {
  for (int w : touching) {
    const Patch& wall = patches[w];
    if (std::abs(glm::dot(wall.normal, a.normal)) > 1.0 - 1e-9) continue;  // coplanar or parallel: no wall between
    if (!(glm::dot(a.normal, wall.centroid - a.centroid) > toleranceM)) continue;  // not standing in front
    const double sideA = glm::dot(wall.normal, a.centroid - wall.vertices[0]);
    const double sideB = glm::dot(wall.normal, b.centroid - wall.vertices[0]);
    if ((sideA > toleranceM && sideB < -toleranceM) || (sideA < -toleranceM && sideB > toleranceM)) return true;
  }
  return false;
}

}  // namespace

DisplayMesh buildDisplayMesh(const std::vector<Patch>& patches) {
  DisplayMesh mesh;
  if (patches.empty()) return mesh;
  const double tolerance = weldTolerance(patches);
  Points points(tolerance);
  std::vector<std::array<int, 4>> pointOf(patches.size());
  std::vector<std::span<const Vec3>> outlines;
  outlines.reserve(patches.size());
  for (size_t p = 0; p < patches.size(); ++p) {
    for (int i = 0; i < patches[p].vertexCount; ++i) pointOf[p][i] = points.indexOf(patches[p].vertices[i]);
    outlines.emplace_back(patches[p].vertices.data(), patches[p].vertexCount);
  }
  // The corners of other patches inside a patch's edges join its outline (T-vertices).
  const std::vector<std::vector<EdgePoint>> edgePoints = findEdgePoints(outlines, points.positions(), tolerance);
  // Per point, the patches with a corner or an edge there.
  std::vector<std::vector<int>> touching(points.positions().size());
  for (size_t p = 0; p < patches.size(); ++p) {
    for (int i = 0; i < patches[p].vertexCount; ++i) touching[pointOf[p][i]].push_back(static_cast<int>(p));
    for (const EdgePoint& e : edgePoints[p]) touching[e.point].push_back(static_cast<int>(p));
  }

  // A point has a vertex per smoothing group of the patches around it: the same material and
  // normal, on the same side of any patch standing there.
  std::vector<std::vector<unsigned>> vertexOfPoint(points.positions().size());
  std::vector<int> firstPatchOf;  // per vertex
  auto vertexAt = [&](int point, int p) {
    const Patch& patch = patches[p];
    for (unsigned vertex : vertexOfPoint[point]) {
      const Patch& first = patches[firstPatchOf[vertex]];
      if (first.material == patch.material && glm::dot(mesh.normals[vertex], patch.normal) > 1.0 - 1e-9 &&
          !separatedAt(touching[point], patch, first, patches, tolerance))
        return vertex;
    }
    const auto vertex = static_cast<unsigned>(mesh.positions.size());
    mesh.positions.push_back(points.positions()[point]);
    mesh.normals.push_back(patch.normal);
    mesh.vertexSources.emplace_back();
    firstPatchOf.push_back(p);
    vertexOfPoint[point].push_back(vertex);
    return vertex;
  };
  std::vector<std::array<unsigned, 4>> corners(patches.size());
  for (size_t p = 0; p < patches.size(); ++p) {
    const Patch& patch = patches[p];
    for (int i = 0; i < patch.vertexCount; ++i) {
      corners[p][i] = vertexAt(pointOf[p][i], static_cast<int>(p));
      // Area weight: a large patch speaks for more of the surface around the vertex.
      mesh.vertexSources[corners[p][i]].emplace_back(static_cast<int>(p), patch.areaM2);
    }
  }

  std::vector<std::vector<unsigned>> edgeVertices(patches.size());  // per edge point, in the patch's group
  struct Interpolated {
    double edgeM;
    int patch, index;
  };
  std::vector<Interpolated> interpolated;
  for (size_t p = 0; p < patches.size(); ++p)
    for (size_t k = 0; k < edgePoints[p].size(); ++k) {
      const EdgePoint& e = edgePoints[p][k];
      edgeVertices[p].push_back(vertexAt(e.point, static_cast<int>(p)));
      const Vec3 d = outlines[p][(e.edge + 1) % outlines[p].size()] - outlines[p][e.edge];
      interpolated.push_back({glm::length(d), static_cast<int>(p), static_cast<int>(k)});
    }
  // A point's radiosity is the edge's, interpolated between its ends, so that shading is
  // continuous across the edge. Longest edges first: an end that lies on a longer edge itself
  // takes its value from that edge before the points between it and the other end do.
  std::sort(interpolated.begin(), interpolated.end(), [](const Interpolated& a, const Interpolated& b) {
    return a.edgeM != b.edgeM ? a.edgeM > b.edgeM : std::pair(a.patch, a.index) < std::pair(b.patch, b.index);
  });
  for (const Interpolated& i : interpolated) {
    const EdgePoint& e = edgePoints[i.patch][i.index];
    const Patch& patch = patches[i.patch];
    const unsigned from = corners[i.patch][e.edge], to = corners[i.patch][(e.edge + 1) % patch.vertexCount];
    mesh.vertexSources[edgeVertices[i.patch][i.index]] =
        alongEdge(mesh.vertexSources[from], mesh.vertexSources[to], e.t);
  }

  std::vector<Vec3> ring;
  std::vector<unsigned> ringVertex;
  std::vector<bool> corner;
  for (size_t p = 0; p < patches.size(); ++p) {
    const Patch& patch = patches[p];
    ring.clear();
    ringVertex.clear();
    corner.clear();
    size_t k = 0;
    for (int i = 0; i < patch.vertexCount; ++i) {
      ring.push_back(mesh.positions[corners[p][i]]);
      ringVertex.push_back(corners[p][i]);
      corner.push_back(true);
      for (; k < edgePoints[p].size() && edgePoints[p][k].edge == i; ++k) {
        ring.push_back(points.positions()[edgePoints[p][k].point]);
        ringVertex.push_back(edgeVertices[p][k]);
        corner.push_back(false);
      }
    }
    // Without edge points, a fan from corner 0: a convex quad splits along (0, 2), which keeps
    // both triangles counter-clockwise.
    for (const std::array<int, 3>& t : triangulateRing(ring, corner)) {
      mesh.indices.insert(mesh.indices.end(), {ringVertex[t[0]], ringVertex[t[1]], ringVertex[t[2]]});
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
