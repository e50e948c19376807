#include "solver/cells/cell_portals.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <unordered_map>

#include "solver/geometry/polygon_2d.h"

namespace radmesh {

namespace {

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

// A plane's frame: n its normal, s and t in it with s x t = n. Coordinates are dot products, which
// for the axes' unit vectors are the components themselves, bit for bit.
struct PlaneFrame {
  Vec3 n, s, t;
  double w(const Vec3& v) const { return glm::dot(n, v); }
  Vec2 in2d(const Vec3& v) const { return {glm::dot(s, v), glm::dot(t, v)}; }
  Vec3 point(double c, Vec2 st) const { return c * n + st.x * s + st.y * t; }
};

PlaneFrame axisFrame(int axis) {
  PlaneFrame f{Vec3(0.0), Vec3(0.0), Vec3(0.0)};
  f.n[axis] = 1.0;
  f.s[(axis + 1) % 3] = 1.0;
  f.t[(axis + 2) % 3] = 1.0;
  return f;
}

// The frame of a plane of normal n (unit), t along the world axis least aligned with it: a wall's
// upright, so that an opening's rectangle stands as a door does.
PlaneFrame obliqueFrame(const Vec3& n) {
  int least = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(n[k]) < std::abs(n[least])) least = k;
  Vec3 up(0.0);
  up[least] = 1.0;
  const Vec3 t = glm::normalize(up - glm::dot(up, n) * n);
  return {n, glm::normalize(glm::cross(t, n)), t};
}

// Whether p lies inside the polygon seen in the frame's plane (the even-odd rule).
bool containsPoint(const std::vector<Vec3>& vs, const PlaneFrame& frame, Vec2 p) {
  bool inside = false;
  for (size_t k = 0, j = vs.size() - 1; k < vs.size(); j = k++) {
    const Vec2 a = frame.in2d(vs[k]), b = frame.in2d(vs[j]);
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (b.x - a.x) * (p.y - a.y) / (b.y - a.y)) inside = !inside;
  }
  return inside;
}

// How far rays from p along +s, -s, +t, -t run in the plane w = c of the frame before they meet a
// polygon (one lying in the plane, or one crossing it); nullopt when p is inside a polygon in the
// plane or a ray runs free.
std::optional<Rect> openingAround(const ScenePolygons& polys, const std::vector<int>& near, const PlaneFrame& frame,
                                  double c, Vec2 p) {
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
  const auto in2d = [&](const Vec3& v) { return frame.in2d(v); };
  for (int index : near) {
    const std::vector<Vec3>& vs = polys.scene.polygons[index].vertices;
    const size_t n = vs.size();
    bool coplanar = true;
    for (const Vec3& v : vs) coplanar = coplanar && std::abs(frame.w(v) - c) <= eps;
    if (coplanar) {
      if (containsPoint(vs, frame, p)) return std::nullopt;
      for (size_t k = 0; k < n; ++k) hitSegment(in2d(vs[k]), in2d(vs[(k + 1) % n]));
      continue;
    }
    std::vector<Vec2> cut;  // where the polygon meets the plane
    for (size_t k = 0; k < n; ++k) {
      const Vec3 &a = vs[k], &b = vs[(k + 1) % n];
      const double da = frame.w(a) - c, db = frame.w(b) - c;
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

// Where cells meet, in a frame: the contact faces' bounds in the plane (box) and across it (cLo,
// cHi), their mean offset and centre.
struct ContactExtent {
  Rect box{kInf, -kInf, kInf, -kInf};
  double cLo = kInf, cHi = -kInf, cMean = 0.0;
  Vec2 centre{0.0};
};

// The contact faces across `axis` (-1: all of them) in the frame: each face a voxel square whose
// corners bound it.
ContactExtent contactExtent(const VoxelGrid& g, const std::vector<Contact>& contacts, int axis, const PlaneFrame& frame) {
  ContactExtent e;
  double cSum = 0.0;
  int count = 0;
  for (const Contact& k : contacts) {
    if (axis >= 0 && k.axis != axis) continue;
    Vec3 lo = g.corner(g.coords(k.low));
    lo[k.axis] += g.voxel;  // the face between the voxel and its +axis neighbour
    const int u = (k.axis + 1) % 3, v = (k.axis + 2) % 3;
    Vec3 centre = lo;
    centre[u] += 0.5 * g.voxel;
    centre[v] += 0.5 * g.voxel;
    for (const double du : {0.0, g.voxel})
      for (const double dv : {0.0, g.voxel}) {
        Vec3 corner = lo;
        corner[u] += du;
        corner[v] += dv;
        const Vec2 st = frame.in2d(corner);
        e.box = {std::min(e.box.s0, st.x), std::max(e.box.s1, st.x), std::min(e.box.t0, st.y), std::max(e.box.t1, st.y)};
      }
    const double c = frame.w(centre);
    e.cLo = std::min(e.cLo, c);
    e.cHi = std::max(e.cHi, c);
    cSum += c;
    e.centre += frame.in2d(centre);
    ++count;
  }
  e.centre /= double(count);
  e.cMean = cSum / count;
  return e;
}

// The smallest opening, among the planes of the frame's polygons near the contact, that matches the
// contact to within `tolerance`: its offset along n and its rectangle.
std::optional<std::pair<double, Rect>> smallestOpening(const ScenePolygons& polys, const PlaneFrame& frame,
                                                       const ContactExtent& e, double reachM, double tolerance) {
  const std::array<double, 3> lo{e.cLo - reachM, e.box.s0 - 2 * tolerance, e.box.t0 - 2 * tolerance};
  const std::array<double, 3> hi{e.cHi + reachM, e.box.s1 + 2 * tolerance, e.box.t1 + 2 * tolerance};
  // The world box that holds that slab of the frame: the polygons' boxes are tested against it first.
  Vec3 worldLo(kInf), worldHi(-kInf);
  for (const double c : {lo[0], hi[0]})
    for (const double u : {lo[1], hi[1]})
      for (const double v : {lo[2], hi[2]}) {
        worldLo = glm::min(worldLo, frame.point(c, {u, v}));
        worldHi = glm::max(worldHi, frame.point(c, {u, v}));
      }
  std::vector<int> near;
  std::vector<double> planes;
  for (size_t i = 0; i < polys.bounds.size(); ++i) {
    const auto& [blo, bhi] = polys.bounds[i];
    if (glm::any(glm::greaterThan(blo, worldHi)) || glm::any(glm::lessThan(bhi, worldLo))) continue;
    // Its extent in the frame (for the axes' frames, its box itself).
    std::array<double, 3> plo{kInf, kInf, kInf}, phi{-kInf, -kInf, -kInf};
    for (const Vec3& v : polys.scene.polygons[i].vertices) {
      const Vec2 st = frame.in2d(v);
      const std::array<double, 3> q{frame.w(v), st.x, st.y};
      for (int k = 0; k < 3; ++k) plo[k] = std::min(plo[k], q[k]), phi[k] = std::max(phi[k], q[k]);
    }
    bool overlaps = true;
    for (int k = 0; k < 3; ++k) overlaps = overlaps && plo[k] <= hi[k] && phi[k] >= lo[k];
    if (!overlaps) continue;
    near.push_back(int(i));
    if (phi[0] - plo[0] <= 1e-9) planes.push_back(plo[0]);
  }
  std::sort(planes.begin(), planes.end());
  planes.erase(std::unique(planes.begin(), planes.end()), planes.end());

  std::optional<std::pair<double, Rect>> best;
  for (double c : planes) {
    const std::optional<Rect> r = openingAround(polys, near, frame, c, e.centre);
    if (!r) continue;
    const Rect& box = e.box;
    const bool covers = r->s0 <= box.s0 + tolerance && r->s1 >= box.s1 - tolerance &&
                        r->t0 <= box.t0 + tolerance && r->t1 >= box.t1 - tolerance;
    const bool within = r->s0 >= box.s0 - tolerance && r->s1 <= box.s1 + tolerance &&
                        r->t0 >= box.t0 - tolerance && r->t1 <= box.t1 + tolerance;
    if (!covers || !within) continue;
    const bool better = !best || r->area() < best->second.area() - 1e-9 ||
                        (r->area() <= best->second.area() + 1e-9 &&
                         std::abs(c - e.cMean) < std::abs(best->first - e.cMean) - 1e-9);
    if (better) best = {c, *r};
  }
  return best;
}

// The unit normals, up to sign, of the polygons near the contact within 30 degrees of `towards`
// and along no axis: the planes of a wall at an angle to the axes. The first of each direction.
std::vector<Vec3> obliqueNormals(const ScenePolygons& polys, const Vec3& towards, const Vec3& nearLo, const Vec3& nearHi) {
  std::vector<Vec3> normals;
  for (size_t i = 0; i < polys.bounds.size(); ++i) {
    const auto& [lo, hi] = polys.bounds[i];
    if (glm::any(glm::greaterThan(lo, nearHi)) || glm::any(glm::lessThan(hi, nearLo))) continue;
    const Vec3 normal = newellNormal(polys.scene.polygons[i].vertices);
    if (!(glm::length(normal) > 0.0)) continue;
    Vec3 n = glm::normalize(normal);
    if (glm::dot(n, towards) < 0.0) n = -n;
    if (glm::dot(n, towards) < std::cos(std::numbers::pi / 6.0)) continue;
    if (std::abs(n.x) == 1.0 || std::abs(n.y) == 1.0 || std::abs(n.z) == 1.0) continue;  // the axes' frames
    if (std::none_of(normals.begin(), normals.end(), [&](const Vec3& m) { return glm::dot(m, n) > 1.0 - 1e-9; }))
      normals.push_back(n);
  }
  return normals;
}

// The portal for one place where cells a < b meet: the smallest opening, among the planes of the
// polygons across the contact's main axis near it, that matches the contact to within 1.5 voxels;
// failing that, the same among the planes of a wall at an angle to the axes, matched to the
// contact's faces across every axis (a staircase of voxels along it), within 2.5 voxels.
Portal portalFor(const VoxelGrid& g, const ScenePolygons& polys, const std::vector<Contact>& contacts, int a, int b,
                 int radius) {
  std::array<int, 3> perAxis{0, 0, 0};
  Vec3 aToB(0.0);
  for (const Contact& k : contacts) {
    ++perAxis[k.axis];
    aToB[k.axis] += k.higherCellAbove ? 1.0 : -1.0;
  }
  const int axis = int(std::max_element(perAxis.begin(), perAxis.end()) - perAxis.begin());
  const double reachM = (radius + 2) * g.voxel;
  PlaneFrame frame = axisFrame(axis);
  const ContactExtent main = contactExtent(g, contacts, axis, frame);
  std::optional<std::pair<double, Rect>> best = smallestOpening(polys, frame, main, reachM, 1.5 * g.voxel);
  if (!best && glm::length(aToB) > 0.0) {
    Vec3 nearLo(kInf), nearHi(-kInf);
    for (const Contact& k : contacts) {
      nearLo = glm::min(nearLo, g.corner(g.coords(k.low)));
      nearHi = glm::max(nearHi, g.corner(g.coords(k.low)) + Vec3(2.0 * g.voxel));
    }
    nearLo -= Vec3(reachM);
    nearHi += Vec3(reachM);
    for (const Vec3& n : obliqueNormals(polys, glm::normalize(aToB), nearLo, nearHi)) {
      const PlaneFrame oblique = obliqueFrame(n);
      const ContactExtent all = contactExtent(g, contacts, -1, oblique);
      const auto found = smallestOpening(polys, oblique, all, reachM, 2.5 * g.voxel);
      if (found && (!best || found->second.area() < best->second.area())) best = found, frame = oblique;
    }
  }
  // Geometry the search does not fit (a curved wall, an arch): the voxels' own rectangle.
  const auto [plane, rect] = best ? *best : std::pair{main.cMean, main.box};

  Portal portal;
  portal.cellA = a;
  portal.cellB = b;
  for (const Vec2 st : {Vec2(rect.s0, rect.t0), Vec2(rect.s1, rect.t0), Vec2(rect.s1, rect.t1), Vec2(rect.s0, rect.t1)})
    portal.vertices.push_back(frame.point(plane, st));
  // Counter-clockwise around n as listed (s x t = n); b lies on its side or not.
  if (glm::dot(frame.n, aToB) < 0.0) std::reverse(portal.vertices.begin(), portal.vertices.end());
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
