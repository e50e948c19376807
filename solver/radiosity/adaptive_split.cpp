#include "solver/radiosity/adaptive_split.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "solver/formfactors/analytic_form_factor.h"
#include "solver/projection/projection.h"

namespace radmesh {

namespace {

constexpr double kPartlyHidden = 0.95;  // a row entry below this share of the unoccluded one
// Sample points are pulled this fraction towards their polygon's centroid, so that a ray from a
// corner does not graze the patches meeting it there.
constexpr double kInset = 1e-3;

struct Box {
  Vec3 lo{0.0}, hi{0.0};
};

Box boxOf(const Patch& p, double margin) {
  Box b{p.vertices[0], p.vertices[0]};
  for (int k = 1; k < p.vertexCount; ++k) {
    b.lo = glm::min(b.lo, p.vertices[k]);
    b.hi = glm::max(b.hi, p.vertices[k]);
  }
  b.lo -= Vec3(margin);
  b.hi += Vec3(margin);
  return b;
}

bool overlap(const Box& a, const Box& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
         b.lo.z <= a.hi.z;
}

// The corners of a polygon pulled kInset towards its centroid, then its centroid.
std::vector<Vec3> samplePoints(const Patch& p) {
  std::vector<Vec3> points;
  for (int k = 0; k < p.vertexCount; ++k) points.push_back(p.vertices[k] + kInset * (p.centroid - p.vertices[k]));
  points.push_back(p.centroid);
  return points;
}

bool crosses(const Vec3& a, const Vec3& b, const Patch& p) {
  const double da = glm::dot(p.normal, a - p.vertices[0]), db = glm::dot(p.normal, b - p.vertices[0]);
  if (!((da > 0.0 && db < 0.0) || (da < 0.0 && db > 0.0))) return false;
  const Vec3 x = a + (da / (da - db)) * (b - a);
  for (int k = 0; k < p.vertexCount; ++k) {
    const Vec3& v = p.vertices[k];
    if (glm::dot(glm::cross(p.vertices[(k + 1) % p.vertexCount] - v, x - v), p.normal) < 0.0) return false;
  }
  return true;
}

}  // namespace

std::vector<std::vector<int>> elementNeighbours(const Elements& elements) {
  const std::vector<Patch>& es = elements.elements;
  std::vector<Box> boxes;
  for (const Patch& e : es) boxes.push_back(boxOf(e, 1e-6 * longestEdge(e)));
  // By polygon, then by the low x of the box: a sweep finds the touching pairs.
  std::vector<int> order(es.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    if (es[a].polygon != es[b].polygon) return es[a].polygon < es[b].polygon;
    return boxes[a].lo.x != boxes[b].lo.x ? boxes[a].lo.x < boxes[b].lo.x : a < b;
  });
  std::vector<std::vector<int>> neighbours(es.size());
  for (size_t i = 0; i < order.size(); ++i) {
    const int a = order[i];
    for (size_t j = i + 1; j < order.size(); ++j) {
      const int b = order[j];
      if (es[b].polygon != es[a].polygon || boxes[b].lo.x > boxes[a].hi.x) break;
      if (!overlap(boxes[a], boxes[b])) continue;
      neighbours[a].push_back(b);
      neighbours[b].push_back(a);
    }
  }
  for (std::vector<int>& n : neighbours) std::sort(n.begin(), n.end());
  return neighbours;
}

bool splittable(const Patch& element, double minElementM) {
  return 0.5 * longestEdge(element) >= minElementM * (1.0 - 1e-9);
}

void markContrast(const Elements& elements, const std::vector<std::vector<int>>& neighbours,
                  const std::vector<double>& reflected, double contrast, double minElementM,
                  std::vector<char>& split) {
  const double brightest = reflected.empty() ? 0.0 : *std::max_element(reflected.begin(), reflected.end());
  const double step = contrast * brightest;
  for (size_t e = 0; e < reflected.size(); ++e)
    for (int n : neighbours[e])
      if (std::abs(reflected[e] - reflected[n]) > step && splittable(elements.elements[e], minElementM)) split[e] = 1;
}

bool segmentBlocked(const Vec3& a, const Vec3& b, const std::vector<Patch>& patches, int skipA, int skipB) {
  const Box segment{glm::min(a, b), glm::max(a, b)};
  for (const Patch& p : patches) {
    if (p.polygon == skipA || p.polygon == skipB) continue;
    if (overlap(segment, boxOf(p, 0.0)) && crosses(a, b, p)) return true;
  }
  return false;
}

int markShadowEdge(const FormFactorRow& row, std::size_t r, const Patch& shooter, const Elements& elements,
                   const std::vector<Patch>& patches, double minElementM, std::vector<char>& split) {
  const int e = row.receivers[r];
  const Patch& element = elements.elements[e];
  if (split[e] || !splittable(element, minElementM)) return 0;
  const double unoccluded = pointToPolygonFormFactor(toShooterFrame(shooter, element).corners());
  if (!(row.formFactors[r] < kPartlyHidden * unoccluded)) return 0;
  std::vector<Vec3> corners = samplePoints(element);
  corners.pop_back();  // the corners alone
  int rays = 0;
  for (const Vec3& light : samplePoints(shooter)) {
    int seen = 0;
    for (const Vec3& corner : corners) seen += segmentBlocked(corner, light, patches, element.polygon, shooter.polygon) ? 0 : 1;
    rays += static_cast<int>(corners.size());
    if (seen > 0 && seen < static_cast<int>(corners.size())) {
      split[e] = 1;
      break;
    }
  }
  return rays;
}

}  // namespace radmesh
