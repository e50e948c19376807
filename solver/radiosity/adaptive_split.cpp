#include "solver/radiosity/adaptive_split.h"

#include <algorithm>
#include <array>
#include <map>
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

using Box = AxisBox;

// An element's box, grown by rounding's reach, so that elements meeting at an edge or a corner overlap.
Box elementBox(const Patch& e) { return boxOf(e, 1e-6 * longestEdge(e)); }

// The corners of a polygon pulled kInset towards its centroid, then its centroid.
std::vector<Vec3> samplePoints(const Patch& p) {
  std::vector<Vec3> points;
  for (int k = 0; k < p.vertexCount; ++k) points.push_back(p.vertices[k] + kInset * (p.centroid - p.vertices[k]));
  points.push_back(p.centroid);
  return points;
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

// Whether a and b (a < b), whose boxes overlap, are neighbours: of one polygon, or of two sharing
// part of an edge and facing. A function of the pair alone (the slack is the lower index's), so
// that the pairs found from scratch and those kept across splits agree bit for bit.
bool neighbourPair(const std::vector<Patch>& es, int a, int b) {
  if (es[a].polygon == es[b].polygon) return true;
  const double slack = 1e-6 * longestEdge(es[a]);
  return facing(es[a], es[b], slack) && shareEdge(es[a], es[b], slack);
}

// Pairs of elements of different polygons whose boxes overlap, added to `overlapping`: each
// element is listed in every bucket of a grid its box meets, so two whose boxes touch share a
// bucket, and an element looks only in the buckets of its own box. The buckets are the median
// element's size (the largest element's would put much of a room in each lookup), but no smaller
// than an eighth of the largest's (which would then be listed in thousands of them).
void addCrossPolygonOverlaps(const std::vector<Patch>& es, const std::vector<Box>& boxes,
                             std::vector<std::vector<int>>& overlapping) {
  std::vector<double> sizes;
  for (const Box& b : boxes) sizes.push_back(glm::length(b.hi - b.lo));
  if (sizes.empty()) return;
  std::nth_element(sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
  const double bucket = std::max(sizes[sizes.size() / 2], *std::max_element(sizes.begin(), sizes.end()) / 8.0);
  if (!(bucket > 0.0)) return;
  PointGrid grid(bucket);
  for (size_t e = 0; e < es.size(); ++e) {
    const Vec3 lo = glm::floor(boxes[e].lo / bucket), hi = glm::floor(boxes[e].hi / bucket);
    for (double x = lo.x; x <= hi.x; ++x)
      for (double y = lo.y; y <= hi.y; ++y)
        for (double z = lo.z; z <= hi.z; ++z) grid.insert(bucket * Vec3(x + 0.5, y + 0.5, z + 0.5), static_cast<int>(e));
  }
  std::vector<int> lastSeenBy(es.size(), -1);  // an element meets `a` in several buckets: one test
  for (size_t a = 0; a < es.size(); ++a) {
    grid.anyInBox(boxes[a].lo, boxes[a].hi, [&](int b) {
      if (b > static_cast<int>(a) && lastSeenBy[b] != static_cast<int>(a) && es[b].polygon != es[a].polygon &&
          overlap(boxes[a], boxes[b])) {
        overlapping[a].push_back(b);
        overlapping[b].push_back(static_cast<int>(a));
      }
      lastSeenBy[b] = static_cast<int>(a);
      return false;
    });
  }
}

// The neighbours among the overlapping pairs, ascending.
std::vector<int> neighboursAmong(const std::vector<Patch>& es, int a, const std::vector<int>& overlapping) {
  std::vector<int> out;
  for (int b : overlapping)
    if (a < b ? neighbourPair(es, a, b) : neighbourPair(es, b, a)) out.push_back(b);
  return out;
}

}  // namespace

ElementAdjacency elementAdjacency(const Elements& elements) {
  const std::vector<Patch>& es = elements.elements;
  ElementAdjacency out;
  std::vector<Box>& boxes = out.boxes;
  for (const Patch& e : es) boxes.push_back(elementBox(e));
  // By polygon, then by the low end of the box along the axis its polygon's elements spread most
  // (along x, a wall in a y-z plane would pair every element with every other): a sweep finds the
  // touching pairs.
  std::map<int, Box> spread;
  for (size_t e = 0; e < es.size(); ++e) {
    const auto [at, fresh] = spread.try_emplace(es[e].polygon, boxes[e]);
    at->second.lo = glm::min(at->second.lo, boxes[e].lo);
    at->second.hi = glm::max(at->second.hi, boxes[e].hi);
  }
  std::vector<int> axis(es.size());
  for (size_t e = 0; e < es.size(); ++e) {
    const Vec3 extent = spread.at(es[e].polygon).hi - spread.at(es[e].polygon).lo;
    axis[e] = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  }
  std::vector<int> order(es.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    if (es[a].polygon != es[b].polygon) return es[a].polygon < es[b].polygon;
    const double la = boxes[a].lo[axis[a]], lb = boxes[b].lo[axis[b]];
    return la != lb ? la < lb : a < b;
  });
  std::vector<std::vector<int>>& overlapping = out.overlapping;
  overlapping.resize(es.size());
  for (size_t i = 0; i < order.size(); ++i) {
    const int a = order[i];
    for (size_t j = i + 1; j < order.size(); ++j) {
      const int b = order[j];
      if (es[b].polygon != es[a].polygon || boxes[b].lo[axis[b]] > boxes[a].hi[axis[a]]) break;
      if (!overlap(boxes[a], boxes[b])) continue;
      overlapping[a].push_back(b);
      overlapping[b].push_back(a);
    }
  }
  addCrossPolygonOverlaps(es, boxes, overlapping);
  out.neighbours.resize(es.size());
  for (size_t a = 0; a < es.size(); ++a) {
    std::sort(overlapping[a].begin(), overlapping[a].end());
    out.neighbours[a] = neighboursAmong(es, static_cast<int>(a), overlapping[a]);
  }
  return out;
}

// A child's box lies within its parent's (its corners are the parent's or midpoints of them, its
// margin is smaller), so two elements whose boxes overlap after a split descend from two whose
// boxes overlapped before: the pairs to look at are the old overlaps' children, nothing else.
void splitAdjacency(ElementAdjacency& adjacency, const Elements& elements, const std::vector<int>& origin,
                    const std::vector<char>& split) {
  const std::vector<Patch>& es = elements.elements;
  const size_t n = es.size();
  // The elements each old one became (itself, or its four children), in order.
  std::vector<int> firstOf(split.size() + 1, 0);
  for (size_t e = 0; e < n; ++e) firstOf[origin[e] + 1] = static_cast<int>(e) + 1;
  for (size_t o = 1; o < firstOf.size(); ++o) firstOf[o] = std::max(firstOf[o], firstOf[o - 1]);
  ElementAdjacency after;
  after.boxes.resize(n);
  after.overlapping.resize(n);
  after.neighbours.resize(n);
  for (size_t e = 0; e < n; ++e) after.boxes[e] = split[origin[e]] ? elementBox(es[e]) : adjacency.boxes[origin[e]];
  for (size_t e = 0; e < n; ++e) {
    const int o = origin[e];
    const bool changed = split[o] || std::ranges::any_of(adjacency.overlapping[o], [&](int old) { return split[old]; });
    if (!changed) {  // the same pairs, in the same order: the lists renumbered where they are
      after.overlapping[e] = std::move(adjacency.overlapping[o]);
      after.neighbours[e] = std::move(adjacency.neighbours[o]);
      for (int& x : after.overlapping[e]) x = firstOf[x];
      for (int& x : after.neighbours[e]) x = firstOf[x];
      continue;
    }
    std::vector<int>& list = after.overlapping[e];
    const auto consider = [&](int old) {
      for (int x = firstOf[old]; x < firstOf[old + 1]; ++x)
        if (x != static_cast<int>(e) && ((!split[o] && !split[old]) || overlap(after.boxes[e], after.boxes[x])))
          list.push_back(x);
    };
    if (split[o]) consider(o);  // the siblings
    for (int old : adjacency.overlapping[o]) consider(old);
    std::sort(list.begin(), list.end());
    after.neighbours[e] = neighboursAmong(es, static_cast<int>(e), list);
  }
  adjacency = std::move(after);
}

bool splittable(const Patch& element, double minElementM) {
  return 0.5 * longestEdge(element) >= minElementM * (1.0 - 1e-9);
}

void markContrast(const Elements& elements, const std::vector<std::vector<int>>& neighbours,
                  const std::vector<double>& reflected, double contrast, double minElementM,
                  std::vector<char>& split) {
  const double brightest = reflected.empty() ? 0.0 : *std::max_element(reflected.begin(), reflected.end());
  const double step = contrastStep(contrast, brightest);
  // The step first: most elements have none, and splittable costs four square roots.
  for (size_t e = 0; e < reflected.size(); ++e)
    if (std::ranges::any_of(neighbours[e], [&](int n) { return stepTooLarge(reflected[e], reflected[n], step); }) &&
        splittable(elements.elements[e], minElementM))
      split[e] = 1;
}

int markShadowEdge(const FormFactorRow& row, std::size_t r, const Patch& shooter, const Elements& elements,
                   const Occluders& occluders, double minElementM, std::vector<char>& split) {
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
    for (const Vec3& corner : corners) seen += occluders.segmentBlocked(corner, light, element.polygon, shooter.polygon) ? 0 : 1;
    rays += static_cast<int>(corners.size());
    if (seen > 0 && seen < static_cast<int>(corners.size())) {
      split[e] = 1;
      break;
    }
  }
  return rays;
}

}  // namespace radmesh
