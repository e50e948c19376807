#include "solver/cells/cell_portals.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <unordered_map>

#include "solver/geometry/polygon_2d.h"

namespace radmesh {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Where two cells touch: the face between voxel `low` and its +axis neighbour.
struct Contact {
  long low = 0;
  int axis = 0;
  bool higherCellAbove = false;  // the larger cell index is on the +axis side
};

struct Rect {
  double s0, s1, t0, t1;
  double area() const { return (s1 - s0) * (t1 - t0); }
};

// Whether p lies inside the polygon seen along `axis` (the even-odd rule).
bool containsPoint(const std::vector<Vec3>& vs, int axis, const Vec3& p) {
  const int s = (axis + 1) % 3, t = (axis + 2) % 3;
  bool inside = false;
  for (size_t k = 0, j = vs.size() - 1; k < vs.size(); j = k++) {
    const Vec3 &a = vs[k], &b = vs[j];
    if ((a[t] > p[t]) != (b[t] > p[t]) && p[s] < a[s] + (b[s] - a[s]) * (p[t] - a[t]) / (b[t] - a[t])) inside = !inside;
  }
  return inside;
}

// How far rays from p along +s, -s, +t, -t run in the plane coordinate[axis] = c before they meet
// a polygon (one lying in the plane, or one crossing it); nullopt when p is inside a polygon in the
// plane or a ray runs free.
std::optional<Rect> openingAround(const ScenePolygons& polys, const std::vector<int>& near, int axis, double c,
                                  Vec2 p) {
  const int s = (axis + 1) % 3, t = (axis + 2) % 3;
  const double eps = 1e-9;
  std::array<double, 4> reach{kInf, kInf, kInf, kInf};  // +s, -s, +t, -t
  auto hitSegment = [&](Vec2 a, Vec2 b) {
    for (int dim = 0; dim < 2; ++dim) {  // rays along s (dim 0) and t (dim 1)
      const int other = 1 - dim;
      const double lo = std::min(a[other], b[other]), hi = std::max(a[other], b[other]);
      if (p[other] < lo - eps || p[other] > hi + eps) continue;
      std::array<double, 2> along{};
      int count = 0;
      if (hi - lo <= eps) {  // the segment runs along the ray: its nearer end counts
        along = {a[dim], b[dim]};
        count = 2;
      } else {
        along[0] = a[dim] + (b[dim] - a[dim]) * (p[other] - a[other]) / (b[other] - a[other]);
        count = 1;
      }
      for (int k = 0; k < count; ++k) {
        const double d = along[k] - p[dim];
        if (d >= 0) reach[2 * dim] = std::min(reach[2 * dim], d);
        if (d <= 0) reach[2 * dim + 1] = std::min(reach[2 * dim + 1], -d);
      }
    }
  };
  auto in2d = [&](const Vec3& v) { return Vec2(v[s], v[t]); };
  for (int index : near) {
    const std::vector<Vec3>& vs = polys.scene.polygons[index].vertices;
    const size_t n = vs.size();
    bool coplanar = true;
    for (const Vec3& v : vs) coplanar = coplanar && std::abs(v[axis] - c) <= eps;
    if (coplanar) {
      Vec3 p3;
      p3[axis] = c;
      p3[s] = p.x;
      p3[t] = p.y;
      if (containsPoint(vs, axis, p3)) return std::nullopt;
      for (size_t k = 0; k < n; ++k) hitSegment(in2d(vs[k]), in2d(vs[(k + 1) % n]));
      continue;
    }
    std::vector<Vec2> cut;  // where the polygon meets the plane
    for (size_t k = 0; k < n; ++k) {
      const Vec3 &a = vs[k], &b = vs[(k + 1) % n];
      const double da = a[axis] - c, db = b[axis] - c;
      if (std::abs(da) <= eps) cut.push_back(in2d(a));
      if ((da > eps && db < -eps) || (da < -eps && db > eps)) cut.push_back(in2d(a + (b - a) * (da / (da - db))));
    }
    if (cut.size() < 2) continue;
    // The extreme points: the whole cut of a convex polygon.
    std::pair<Vec2, Vec2> ends{cut[0], cut[0]};
    double longest = -1.0;
    for (const Vec2& a : cut)
      for (const Vec2& b : cut)
        if (glm::length(b - a) > longest) {
          longest = glm::length(b - a);
          ends = {a, b};
        }
    hitSegment(ends.first, ends.second);
  }
  for (double r : reach)
    if (!(r < kInf) || r <= eps) return std::nullopt;
  return Rect{p.x - reach[1], p.x + reach[0], p.y - reach[3], p.y + reach[2]};
}

// The portal for one place where cells a < b meet: the smallest opening, among the planes of the
// polygons across the contact's axis near it, that matches the contact to within 1.5 voxels.
Portal portalFor(const VoxelGrid& g, const ScenePolygons& polys, const std::vector<Contact>& contacts, int a, int b,
                 int radius) {
  std::array<int, 3> perAxis{0, 0, 0};
  for (const Contact& k : contacts) ++perAxis[k.axis];
  const int axis = int(std::max_element(perAxis.begin(), perAxis.end()) - perAxis.begin());
  const int s = (axis + 1) % 3, t = (axis + 2) % 3;
  Rect box{kInf, -kInf, kInf, -kInf};
  double cLo = kInf, cHi = -kInf, cSum = 0.0;
  Vec2 centre(0.0);
  int count = 0, bAbove = 0;
  for (const Contact& k : contacts) {
    if (k.axis != axis) continue;
    const Vec3 lo = g.corner(g.coords(k.low));
    const double c = lo[axis] + g.voxel;
    box = {std::min(box.s0, lo[s]), std::max(box.s1, lo[s] + g.voxel), std::min(box.t0, lo[t]),
           std::max(box.t1, lo[t] + g.voxel)};
    cLo = std::min(cLo, c);
    cHi = std::max(cHi, c);
    cSum += c;
    centre += Vec2(lo[s], lo[t]) + 0.5 * g.voxel;
    ++count;
    bAbove += k.higherCellAbove ? 1 : 0;
  }
  centre /= double(count);
  const double cMean = cSum / count;
  const double reachM = (radius + 2) * g.voxel, tolerance = 1.5 * g.voxel;

  Vec3 nearLo(0.0), nearHi(0.0);
  nearLo[axis] = cLo - reachM;
  nearHi[axis] = cHi + reachM;
  nearLo[s] = box.s0 - 2 * tolerance;
  nearHi[s] = box.s1 + 2 * tolerance;
  nearLo[t] = box.t0 - 2 * tolerance;
  nearHi[t] = box.t1 + 2 * tolerance;
  std::vector<int> near;
  std::vector<double> planes;
  for (size_t i = 0; i < polys.bounds.size(); ++i) {
    const auto& [lo, hi] = polys.bounds[i];
    if (glm::any(glm::greaterThan(lo, nearHi)) || glm::any(glm::lessThan(hi, nearLo))) continue;
    near.push_back(int(i));
    if (hi[axis] - lo[axis] <= 1e-9) planes.push_back(lo[axis]);
  }
  std::sort(planes.begin(), planes.end());
  planes.erase(std::unique(planes.begin(), planes.end()), planes.end());

  std::optional<std::pair<double, Rect>> best;
  for (double c : planes) {
    const std::optional<Rect> r = openingAround(polys, near, axis, c, centre);
    if (!r) continue;
    const bool covers = r->s0 <= box.s0 + tolerance && r->s1 >= box.s1 - tolerance &&
                        r->t0 <= box.t0 + tolerance && r->t1 >= box.t1 - tolerance;
    const bool within = r->s0 >= box.s0 - tolerance && r->s1 <= box.s1 + tolerance &&
                        r->t0 >= box.t0 - tolerance && r->t1 <= box.t1 + tolerance;
    if (!covers || !within) continue;
    const bool better = !best || r->area() < best->second.area() - 1e-9 ||
                        (r->area() <= best->second.area() + 1e-9 &&
                         std::abs(c - cMean) < std::abs(best->first - cMean) - 1e-9);
    if (better) best = {c, *r};
  }
  // Geometry the search does not fit (a slanted wall, an arch): the voxels' own rectangle.
  const auto [plane, rect] = best ? *best : std::pair{cMean, box};

  Portal portal;
  portal.cellA = a;
  portal.cellB = b;
  for (const auto& [cs, ct] : {std::pair{rect.s0, rect.t0}, {rect.s1, rect.t0}, {rect.s1, rect.t1}, {rect.s0, rect.t1}}) {
    Vec3 v;
    v[axis] = plane;
    v[s] = cs;
    v[t] = ct;
    portal.vertices.push_back(v);
  }
  // Counter-clockwise around +axis as listed (s, t, axis run cyclically); b lies on its side or not.
  if (2 * bAbove < count) std::reverse(portal.vertices.begin(), portal.vertices.end());
  portal.areaM2 = rect.area();
  return portal;
}

}  // namespace

ScenePolygons::ScenePolygons(const Scene& s) : scene(s) {
  for (const Polygon& p : s.polygons) {
    Vec3 lo(kInf), hi(-kInf);
    for (const Vec3& v : p.vertices) {
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
    bounds.emplace_back(lo, hi);
  }
}

// Whether the segment a..b passes through a polygon other than `own`.
bool segmentBlocked(const ScenePolygons& polys, int own, const Vec3& a, const Vec3& b) {
  const Vec3 lo = glm::min(a, b), hi = glm::max(a, b);
  for (size_t i = 0; i < polys.bounds.size(); ++i) {
    const auto& [plo, phi] = polys.bounds[i];
    if (int(i) == own || glm::any(glm::greaterThan(plo, hi)) || glm::any(glm::lessThan(phi, lo))) continue;
    const std::vector<Vec3>& vs = polys.scene.polygons[i].vertices;
    const Vec3 n = newellNormal(vs);
    const double da = glm::dot(n, a - vs[0]), db = glm::dot(n, b - vs[0]);
    if ((da > 0.0) == (db > 0.0) || da == db) continue;
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (std::abs(n[k]) > std::abs(n[axis])) axis = k;
    if (containsPoint(vs, axis, a + (b - a) * (da / (da - db)))) return true;
  }
  return false;
}

// Each place two cells meet: the contacts between each pair of cells, split into connected
// groups (faces within a voxel of each other), in voxel order.
std::vector<Portal> findPortals(const VoxelGrid& g, const VoxelLabels& labels, const ScenePolygons& polys, int radius) {
  std::map<std::pair<int, int>, std::vector<Contact>> byPair;
  for (long i = 0; i < g.size(); ++i) {
    const std::int32_t a = labels.label[i];
    if (a < 0) continue;
    const Index3 v = g.coords(i);
    for (int axis = 0; axis < 3; ++axis) {
      if (v[axis] + 1 >= g.n[axis]) continue;
      const std::int32_t b = labels.label[i + g.stride(axis)];
      if (b < 0 || b == a) continue;
      byPair[{std::min(a, b), std::max(a, b)}].push_back({i, axis, b > a});
    }
  }
  std::vector<Portal> portals;
  for (const auto& [pair, contacts] : byPair) {
    std::unordered_map<long, int> at;  // low voxel * 3 + axis -> contact
    for (size_t k = 0; k < contacts.size(); ++k) at[contacts[k].low * 3 + contacts[k].axis] = int(k);
    std::vector<int> group(contacts.size(), -1);
    int groups = 0;
    for (size_t first = 0; first < contacts.size(); ++first) {
      if (group[first] >= 0) continue;
      std::vector<int> stack{int(first)};
      group[first] = groups;
      std::vector<Contact> members;
      while (!stack.empty()) {
        const Contact k = contacts[stack.back()];
        stack.pop_back();
        members.push_back(k);
        const Index3 v = g.coords(k.low);
        for (int dz = -1; dz <= 1; ++dz)
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              const Index3 w{v[0] + dx, v[1] + dy, v[2] + dz};
              if (!g.inside(w)) continue;
              for (int axis = 0; axis < 3; ++axis) {
                const auto it = at.find(g.index(w) * 3 + axis);
                if (it == at.end() || group[it->second] >= 0) continue;
                group[it->second] = groups;
                stack.push_back(it->second);
              }
            }
      }
      ++groups;
      Portal portal = portalFor(g, polys, members, pair.first, pair.second, radius);
      const bool seen = std::any_of(portals.begin(), portals.end(), [&](const Portal& q) {
        if (q.cellA != portal.cellA || q.cellB != portal.cellB) return false;
        for (size_t k = 0; k < q.vertices.size(); ++k)
          if (glm::length(q.vertices[k] - portal.vertices[k]) > 1e-9) return false;
        return true;
      });
      if (!seen) portals.push_back(std::move(portal));
    }
  }
  return portals;
}

}  // namespace radmesh
