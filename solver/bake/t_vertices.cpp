#include "solver/bake/t_vertices.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "solver/geometry/point_grid.h"

namespace radmesh {

namespace {

// The triangle's smallest angle (radians): how far it is from degenerate.
double smallestAngle(const Vec3& a, const Vec3& b, const Vec3& c) {
  auto angle = [](const Vec3& at, const Vec3& p, const Vec3& q) {
    const double lengths = glm::length(p - at) * glm::length(q - at);
    return lengths > 0.0 ? std::acos(std::clamp(glm::dot(p - at, q - at) / lengths, -1.0, 1.0)) : 0.0;
  };
  return std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
}

}  // namespace

std::vector<std::vector<EdgePoint>> findEdgePoints(std::span<const std::span<const Vec3>> outlines,
                                                   std::span<const Vec3> points, double toleranceM) {
  // Buckets twice as wide as the median edge is long: an edge's box meets a few of them, each
  // holding a few points (the mean edge is set by a few long ones, and crowds small detail; the
  // office3 model cut into elements builds fastest at twice the median).
  std::vector<double> lengths;
  for (std::span<const Vec3> outline : outlines)
    for (size_t i = 0; i < outline.size(); ++i) lengths.push_back(glm::length(outline[(i + 1) % outline.size()] - outline[i]));
  double bucketM = 1.0;
  if (!lengths.empty()) {
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    bucketM = lengths[lengths.size() / 2];
  }
  PointGrid grid(std::max(64.0 * toleranceM, 2.0 * bucketM));
  for (size_t p = 0; p < points.size(); ++p) grid.insert(points[p], static_cast<int>(p));

  std::vector<std::vector<EdgePoint>> out(outlines.size());
  std::vector<EdgePoint> onEdge;
  for (size_t o = 0; o < outlines.size(); ++o) {
    const std::span<const Vec3> outline = outlines[o];
    for (size_t e = 0; e < outline.size(); ++e) {
      const Vec3 a = outline[e], b = outline[(e + 1) % outline.size()], d = b - a;
      const double length2 = glm::dot(d, d);
      if (length2 <= toleranceM * toleranceM) continue;
      onEdge.clear();
      const Vec3 lo = glm::min(a, b) - Vec3(toleranceM), hi = glm::max(a, b) + Vec3(toleranceM);
      grid.anyInBox(lo, hi, [&](int p) {
        if (glm::any(glm::lessThan(points[p], lo)) || glm::any(glm::greaterThan(points[p], hi))) return false;
        const Vec3 ap = points[p] - a;
        const double t = glm::dot(ap, d) / length2;
        if (t > 0.0 && t < 1.0 && glm::length(ap - t * d) <= toleranceM && glm::length(ap) > toleranceM &&
            glm::length(points[p] - b) > toleranceM)
          onEdge.push_back({static_cast<int>(e), t, p});
        return false;
      });
      std::sort(onEdge.begin(), onEdge.end(),
                [](const EdgePoint& x, const EdgePoint& y) { return x.t != y.t ? x.t < y.t : x.point < y.point; });
      for (const EdgePoint& found : onEdge)
        if (out[o].empty() || out[o].back().edge != found.edge ||
            glm::length(points[found.point] - points[out[o].back().point]) > toleranceM)
          out[o].push_back(found);
    }
  }
  return out;
}

std::vector<std::array<int, 3>> triangulateRing(std::span<const Vec3> ring, std::vector<bool> corner) {
  std::vector<int> left(ring.size());  // the ring still to triangulate
  std::iota(left.begin(), left.end(), 0);
  std::vector<std::array<int, 3>> triangles;
  while (left.size() >= 3) {
    const size_t m = left.size();
    auto at = [&](size_t k, int step) { return left[(k + m + step) % m]; };
    for (size_t k = 0; k < m; ++k)
      if (m == 3 || (corner[at(k, 0)] && corner[at(k, -1)] && corner[at(k, 1)])) {
        for (size_t j = 1; j + 1 < m; ++j) triangles.push_back({at(k, 0), at(k, int(j)), at(k, int(j) + 1)});
        return triangles;
      }
    // No fan yet: cut off the best-shaped ear at a corner; its neighbours become corners.
    size_t best = 0;
    double bestAngle = -1.0;
    for (size_t k = 0; k < m; ++k) {
      if (!corner[at(k, 0)]) continue;
      const double angle = smallestAngle(ring[at(k, -1)], ring[at(k, 0)], ring[at(k, 1)]);
      if (angle > bestAngle) {
        bestAngle = angle;
        best = k;
      }
    }
    triangles.push_back({at(best, -1), at(best, 0), at(best, 1)});
    corner[at(best, -1)] = corner[at(best, 1)] = true;
    left.erase(left.begin() + static_cast<std::ptrdiff_t>(best));
  }
  return triangles;
}

}  // namespace radmesh
