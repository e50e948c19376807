#include "solver/radiosity/adaptive_split.h"

#include <algorithm>
#include <array>
#include <numeric>

#include "solver/geometry/point_grid.h"
#include "solver/formfactors/analytic_form_factor.h"
#include "solver/meshing/gradient_criterion.h"
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

// Whether an edge of `a` and an edge of `b` lie on one line and overlap over more than `slack`.
bool shareEdge(const Patch& a, const Patch& b, double slack) {
  for (int i = 0; i < a.vertexCount; ++i) {
    const Vec3 p = a.vertices[i], d = a.vertices[(i + 1) % a.vertexCount] - p;
    const double length = glm::length(d);
    const Vec3 u = d / length;
    for (int k = 0; k < b.vertexCount; ++k) {
      const Vec3 q0 = b.vertices[k] - p, q1 = b.vertices[(k + 1) % b.vertexCount] - p;
      if (glm::length(glm::cross(u, q0)) > slack || glm::length(glm::cross(u, q1)) > slack) continue;
      const double t0 = glm::dot(u, q0), t1 = glm::dot(u, q1);
      if (std::min(length, std::max(t0, t1)) - std::max(0.0, std::min(t0, t1)) > slack) return true;
    }
  }
  return false;
}

// Whether light can pass between elements of two polygons meeting at an edge: coplanar, or a
// concave fold (each in front of the other). Not a convex fold (each behind the other: the seam is
// an outline, whose step is geometry) nor two faces back to back.
bool facing(const Patch& a, const Patch& b, double slack) {
  return glm::dot(a.normal, b.normal) > -0.9 && glm::dot(a.normal, b.centroid - a.centroid) >= -slack &&
         glm::dot(b.normal, a.centroid - b.centroid) >= -slack;
}

// Pairs of elements of different polygons sharing part of an edge (and facing), added to
// `neighbours`: found through a grid of element centroids, each looked up within its box grown by
// half the largest element's extent.
void addCrossPolygonNeighbours(const std::vector<Patch>& es, const std::vector<Box>& boxes,
                               std::vector<std::vector<int>>& neighbours) {
  double extent = 0.0;
  for (const Box& b : boxes) extent = std::max(extent, glm::length(b.hi - b.lo));
  if (!(extent > 0.0)) return;
  PointGrid grid(extent);
  for (size_t e = 0; e < es.size(); ++e) grid.insert(es[e].centroid, static_cast<int>(e));
  for (size_t a = 0; a < es.size(); ++a) {
    const double slack = 1e-6 * longestEdge(es[a]);
    grid.anyInBox(boxes[a].lo - Vec3(0.5 * extent), boxes[a].hi + Vec3(0.5 * extent), [&](int b) {
      if (b > static_cast<int>(a) && es[b].polygon != es[a].polygon && overlap(boxes[a], boxes[b]) &&
          facing(es[a], es[b], slack) && shareEdge(es[a], es[b], slack)) {
        neighbours[a].push_back(b);
        neighbours[b].push_back(static_cast<int>(a));
      }
      return false;
    });
  }
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
  addCrossPolygonNeighbours(es, boxes, neighbours);
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
  const double step = contrastStep(contrast, brightest);
  for (size_t e = 0; e < reflected.size(); ++e)
    for (int n : neighbours[e])
      if (stepTooLarge(reflected[e], reflected[n], step) && splittable(elements.elements[e], minElementM)) split[e] = 1;
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
