#include "solver/formfactors/analytic_form_factor.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
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

namespace {

// The integral of ln r over the edge from a along the unit direction u for length `length`, r the
// distance from p, less the edge's length: with s the position along the edge's line from p's
// foot and d p's distance from that line, G(s) = s ln sqrt(s^2 + d^2) + d atan(s / d) between the
// ends. (The length, a constant per edge, drops out of the sum over a closed contour.)
double lnDistanceAlongEdge(const Vec3& p, const Vec3& a, const Vec3& u, double length) {
  const Vec3 w = p - a;
  const double foot = glm::dot(w, u), d = glm::length(glm::cross(w, u));  // d without cancellation
  auto G = [&](double s) {
    const double r2 = s * s + d * d;
    const double logTerm = r2 > 0.0 ? 0.5 * s * std::log(r2) : 0.0;  // s ln r -> 0 as both vanish
    return logTerm + (d > 0.0 ? d * std::atan(s / d) : 0.0);
  };
  return G(length - foot) - G(-foot);
}

// The integral of ln r dp.dq over an edge pair, r the distance between a point of each: along
// the first edge by 8-point Gauss-Legendre, halved where the halves disagree with the whole (the
// integrand bends sharply only within a gap's width of the other edge, so the halving gathers
// there), along the second in closed form (lnDistanceAlongEdge).
class EdgePair {
 public:
  EdgePair(const Vec3& p, const Vec3& pEnd, const Vec3& q, const Vec3& qEnd)
      : p_(p), u_(pEnd - p), q_(q), v_(qEnd - q), pLength_(glm::length(u_)), qLength_(glm::length(v_)) {
    if (pLength_ > 0.0) u_ /= pLength_;
    if (qLength_ > 0.0) v_ /= qLength_;
  }
  // tolerance: of the whole edge's integral; each half keeps its share.
  double integral(double tolerance) const {
    const double cosine = glm::dot(u_, v_);
    if (!(pLength_ > 0.0) || !(qLength_ > 0.0) || cosine == 0.0) return 0.0;  // no length, or dp.dq = 0
    return cosine * refine(0.0, pLength_, gauss(0.0, pLength_), tolerance, kMostHalvings);
  }

 private:
  static constexpr int kMostHalvings = 24;
  double gauss(double lo, double hi) const {
    static constexpr std::array<double, 4> kNode{0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                                  0.9602898564975363};
    static constexpr std::array<double, 4> kWeight{0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                                   0.1012285362903763};
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    double sum = 0.0;
    for (size_t k = 0; k < kNode.size(); ++k)
      sum += kWeight[k] * (lnDistanceAlongEdge(p_ + (mid - half * kNode[k]) * u_, q_, v_, qLength_) +
                           lnDistanceAlongEdge(p_ + (mid + half * kNode[k]) * u_, q_, v_, qLength_));
    return sum * half;
  }
  double refine(double lo, double hi, double whole, double tolerance, int halvings) const {
    const double mid = 0.5 * (lo + hi), left = gauss(lo, mid), right = gauss(mid, hi);
    // Never asks for more than rounding leaves, which would halve without end.
    const double enough = std::max(tolerance, 64.0 * std::numeric_limits<double>::epsilon() * std::abs(left + right));
    if (halvings == 0 || std::abs(left + right - whole) <= enough) return left + right;
    return refine(lo, mid, left, 0.5 * tolerance, halvings - 1) + refine(mid, hi, right, 0.5 * tolerance, halvings - 1);
  }

  Vec3 p_, u_, q_, v_;
  double pLength_, qLength_;
};

double polygonArea(std::span<const Vec3> v) {
  Vec3 twice(0.0);
  for (size_t k = 0; k < v.size(); ++k) twice += glm::cross(v[k], v[(k + 1) % v.size()]);
  return 0.5 * glm::length(twice);
}

}  // namespace

double polygonToPolygonFormFactor(std::span<const Vec3> from, std::span<const Vec3> to) {
  const double area = polygonArea(from);
  if (!(area > 0.0)) return 0.0;
  // The terms are about area x (1 + |ln size|) each; ask for their last few digits.
  const double size = std::sqrt(std::max(squaredDiameter(from), squaredDiameter(to)));
  const double tolerance = 1e-13 * area * (1.0 + std::abs(std::log(size)));
  double sum = 0.0;
  for (size_t i = 0; i < from.size(); ++i)
    for (size_t j = 0; j < to.size(); ++j)
      sum += EdgePair(from[i], from[(i + 1) % from.size()], to[j], to[(j + 1) % to.size()]).integral(tolerance);
  return std::abs(sum) / (2.0 * std::numbers::pi * area);
}

}  // namespace radmesh
