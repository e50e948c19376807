#include "solver/cells/find_cells.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <tuple>
#include <unordered_map>

#include "solver/geometry/polygon_2d.h"

namespace radmesh {

namespace {

// docs/cells.md explains the method: free space voxelised, eroded by a cube so that narrow
// openings close, its connected parts the rooms' cores (those touching the grid's border: the
// outside), grown back over free space breadth-first, and each place two cells meet turned into
// the exact rectangle of the opening there.
constexpr double kCutRadiusM = 0.6;  // openings less than about twice this wide are cut: doors, windows
constexpr double kVoxelM = kCutRadiusM / 4;
constexpr double kMaxVoxels = 24e6;  // bounds the memory at about 6 bytes a voxel
constexpr double kInf = std::numeric_limits<double>::infinity();

constexpr std::int32_t kUnreached = -2;  // free, but joined to no core (inside a wall's thickness)
constexpr std::int32_t kSolid = -3;
constexpr int kOutsideHandicap = 6;  // layers: where cell and outside meet moves 3 voxels outward

using Index3 = std::array<int, 3>;

struct Grid {
  Vec3 origin{0.0};
  double voxel = kVoxelM;
  Index3 n{0, 0, 0};
  long size() const { return long(n[0]) * n[1] * n[2]; }
  long index(const Index3& v) const { return (long(v[2]) * n[1] + v[1]) * n[0] + v[0]; }
  Index3 coords(long i) const { return {int(i % n[0]), int(i / n[0] % n[1]), int(i / (long(n[0]) * n[1]))}; }
  long stride(int axis) const { return axis == 0 ? 1 : axis == 1 ? n[0] : long(n[0]) * n[1]; }
  bool inside(const Index3& v) const {
    return v[0] >= 0 && v[1] >= 0 && v[2] >= 0 && v[0] < n[0] && v[1] < n[1] && v[2] < n[2];
  }
  Index3 voxelOf(const Vec3& p) const {
    Index3 v;
    for (int a = 0; a < 3; ++a) v[a] = int(std::floor((p[a] - origin[a]) / voxel));
    return v;
  }
  Vec3 corner(const Index3& v) const { return origin + voxel * Vec3(v[0], v[1], v[2]); }
};

std::pair<Vec3, Vec3> boundsOf(const Patch& p) {
  Vec3 lo(kInf), hi(-kInf);
  for (int k = 0; k < p.vertexCount; ++k) {
    lo = glm::min(lo, p.vertices[k]);
    hi = glm::max(hi, p.vertices[k]);
  }
  return {lo, hi};
}

std::pair<Vec3, Vec3> boundsOf(const std::vector<Patch>& patches) {
  Vec3 lo(kInf), hi(-kInf);
  for (const Patch& p : patches) {
    const auto [a, b] = boundsOf(p);
    lo = glm::min(lo, a);
    hi = glm::max(hi, b);
  }
  return {lo, hi};
}

// The grid over the patches' bounds with `pad` free voxels around, its voxel enlarged from
// kVoxelM only where the building would take more than kMaxVoxels.
Grid makeGrid(const std::vector<Patch>& patches, int& pad) {
  const auto [lo, hi] = boundsOf(patches);
  Grid g;
  const Vec3 size = hi - lo;
  g.voxel = std::max(kVoxelM, std::cbrt(size.x * size.y * size.z / kMaxVoxels));
  pad = int(std::ceil(kCutRadiusM / g.voxel - 1e-9)) + 2;
  g.origin = lo - double(pad) * g.voxel;
  for (int a = 0; a < 3; ++a) g.n[a] = int(std::ceil(size[a] / g.voxel - 1e-9)) + 2 * pad;
  return g;
}

// Separating-axis test of a convex patch against the box lo..hi; touching counts as overlapping.
bool patchTouchesBox(const Patch& p, const Vec3& lo, const Vec3& hi) {
  const Vec3 centre = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  const double slack = 1e-9;
  auto separates = [&](const Vec3& axis) {
    double mn = kInf, mx = -kInf;
    for (int k = 0; k < p.vertexCount; ++k) {
      const double d = glm::dot(axis, p.vertices[k] - centre);
      mn = std::min(mn, d);
      mx = std::max(mx, d);
    }
    const double r = glm::dot(half, glm::abs(axis)) + slack;
    return mn > r || mx < -r;
  };
  if (separates(p.normal)) return false;
  for (int k = 0; k < p.vertexCount; ++k) {
    const Vec3 edge = p.vertices[(k + 1) % p.vertexCount] - p.vertices[k];
    for (int a = 0; a < 3; ++a) {
      Vec3 unit(0.0);
      unit[a] = 1.0;
      const Vec3 axis = glm::cross(edge, unit);
      if (glm::dot(axis, axis) > 1e-24 && separates(axis)) return false;
    }
  }
  return true;
}

std::vector<std::uint8_t> voxelise(const Grid& g, const std::vector<Patch>& patches) {
  std::vector<std::uint8_t> solid(g.size(), 0);
  for (const Patch& p : patches) {
    const auto [lo, hi] = boundsOf(p);
    const double e = 1e-9;
    const Index3 a = g.voxelOf(lo - Vec3(e)), b = g.voxelOf(hi + Vec3(e));
    for (int z = a[2]; z <= b[2]; ++z)
      for (int y = a[1]; y <= b[1]; ++y)
        for (int x = a[0]; x <= b[0]; ++x) {
          const Index3 v{x, y, z};
          const long i = g.index(v);
          if (!solid[i] && patchTouchesBox(p, g.corner(v), g.corner({x + 1, y + 1, z + 1}))) solid[i] = 1;
        }
  }
  return solid;
}

// `mask` grown by r voxels along `axis` (one pass of a cube dilation).
void dilateAlong(const Grid& g, std::vector<std::uint8_t>& mask, int axis, int r) {
  const long stride = g.stride(axis);
  const int length = g.n[axis], u = (axis + 1) % 3, w = (axis + 2) % 3;
  std::vector<std::uint8_t> line(length);
  for (int j = 0; j < g.n[w]; ++j)
    for (int i = 0; i < g.n[u]; ++i) {
      const long start = i * g.stride(u) + j * g.stride(w);
      for (int k = 0; k < length; ++k) line[k] = mask[start + k * stride];
      for (int direction : {1, -1}) {
        int since = r + 1;  // voxels since the last set one
        for (int k = direction > 0 ? 0 : length - 1; k >= 0 && k < length; k += direction) {
          since = line[k] ? 0 : since + 1;
          if (since <= r) mask[start + k * stride] = 1;
        }
      }
    }
}

// The six face neighbours of voxel i that lie in the grid.
template <class F>
void forNeighbours(const Grid& g, long i, F&& f) {
  const Index3 v = g.coords(i);
  for (int a = 0; a < 3; ++a) {
    if (v[a] > 0) f(i - g.stride(a));
    if (v[a] + 1 < g.n[a]) f(i + g.stride(a));
  }
}

struct Labels {
  std::vector<std::int32_t> label;  // per voxel: a cell, kOutsideCell, kUnreached or kSolid
  int cells = 0;
};

// Cores: the connected parts of the eroded free space, outside those touching the border; then
// every free voxel takes the label of the core nearest to it (breadth-first, 6-connected).
Labels labelVoxels(const Grid& g, const std::vector<std::uint8_t>& solid, int radius) {
  std::vector<std::uint8_t> blocked = solid;
  for (int a = 0; a < 3; ++a) dilateAlong(g, blocked, a, radius);
  Labels out;
  out.label.assign(g.size(), kUnreached);
  for (long i = 0; i < g.size(); ++i)
    if (solid[i]) out.label[i] = kSolid;
  std::vector<long> queue;
  std::vector<long> seeds;
  for (long start = 0; start < g.size(); ++start) {
    if (blocked[start] || out.label[start] != kUnreached) continue;
    queue.assign(1, start);
    out.label[start] = out.cells;
    bool border = false;
    for (size_t head = 0; head < queue.size(); ++head) {
      const Index3 v = g.coords(queue[head]);
      for (int a = 0; a < 3; ++a) border = border || v[a] == 0 || v[a] + 1 == g.n[a];
      forNeighbours(g, queue[head], [&](long j) {
        if (!blocked[j] && out.label[j] == kUnreached) {
          out.label[j] = out.cells;
          queue.push_back(j);
        }
      });
    }
    if (border)
      for (long i : queue) out.label[i] = kOutsideCell;
    else
      ++out.cells;
    seeds.insert(seeds.end(), queue.begin(), queue.end());
  }
  // Grown a layer at a time from the cores in the order found, so that ties go the same way every
  // time (to the lower cell); the cells kOutsideHandicap layers ahead of the outside, so that the
  // passage of a window belongs to its room.
  std::vector<long> frontier, outside;
  for (long i : seeds) (out.label[i] == kOutsideCell ? outside : frontier).push_back(i);
  for (int layer = 0; !frontier.empty() || !outside.empty(); ++layer) {
    if (layer == kOutsideHandicap) {
      frontier.insert(frontier.end(), outside.begin(), outside.end());
      outside.clear();
    }
    std::vector<long> next;
    for (long i : frontier) {
      const std::int32_t l = out.label[i];
      forNeighbours(g, i, [&](long j) {
        if (out.label[j] == kUnreached) {
          out.label[j] = l;
          next.push_back(j);
        }
      });
    }
    frontier = std::move(next);
  }
  return out;
}

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

// The scene's polygons with their bounds, for the opening search.
struct Polygons {
  const Scene& scene;
  std::vector<std::pair<Vec3, Vec3>> bounds;
  explicit Polygons(const Scene& s) : scene(s) {
    for (const Polygon& p : s.polygons) {
      Vec3 lo(kInf), hi(-kInf);
      for (const Vec3& v : p.vertices) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
      }
      bounds.emplace_back(lo, hi);
    }
  }
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

// Whether the segment a..b passes through a polygon other than `own`.
bool segmentBlocked(const Polygons& polys, int own, const Vec3& a, const Vec3& b) {
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

// How far rays from p along +s, -s, +t, -t run in the plane coordinate[axis] = c before they meet
// a polygon (one lying in the plane, or one crossing it); nullopt when p is inside a polygon in the
// plane or a ray runs free.
std::optional<Rect> openingAround(const Polygons& polys, const std::vector<int>& near, int axis, double c,
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
Portal portalFor(const Grid& g, const Polygons& polys, const std::vector<Contact>& contacts, int a, int b,
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

// Each place two cells meet: the contacts between each pair of cells, split into connected
// groups (faces within a voxel of each other), in voxel order.
std::vector<Portal> findPortals(const Grid& g, const Labels& labels, const Polygons& polys, int radius) {
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

// The label of the voxel next to the patch's own along its normal's main axis; kUnreached when it
// is solid (a face in a gap narrower than a voxel, or within a voxel of a wall across it), or
// when it is outside but a polygon lies between (the back of a cabinet 2 cm from an exterior wall).
std::int32_t labelAhead(const Grid& g, const Labels& labels, const Polygons& polys, const Patch& p) {
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (std::abs(p.normal[a]) > std::abs(p.normal[axis])) axis = a;
  // The patch's own voxel, on the front side when it lies on a voxel boundary (both are solid).
  Index3 v = g.voxelOf(p.centroid + p.normal * (1e-6 * g.voxel));
  v[axis] += p.normal[axis] > 0 ? 1 : -1;
  if (!g.inside(v)) return kOutsideCell;
  const std::int32_t l = labels.label[g.index(v)];
  if (l == kOutsideCell && segmentBlocked(polys, p.polygon, p.centroid, g.corner(v) + 0.5 * g.voxel)) return kUnreached;
  return l >= kOutsideCell ? l : kUnreached;
}

// The nearest cell voxel in front of the patch within `reach` voxels, else the nearest one behind
// it (a face towards a wall a few centimetres away: the back of a cabinet), else kOutsideCell.
int nearestCell(const Grid& g, const Labels& labels, const Patch& p, int reach) {
  const Vec3 start = p.centroid + p.normal * (0.75 * g.voxel);
  const Index3 c = g.voxelOf(start);
  std::array<int, 2> found{kOutsideCell, kOutsideCell};  // in front, behind
  std::array<double, 2> nearest{kInf, kInf};
  for (int dz = -reach; dz <= reach; ++dz)
    for (int dy = -reach; dy <= reach; ++dy)
      for (int dx = -reach; dx <= reach; ++dx) {
        const Index3 v{c[0] + dx, c[1] + dy, c[2] + dz};
        if (!g.inside(v)) continue;
        const std::int32_t l = labels.label[g.index(v)];
        if (l < 0) continue;
        const Vec3 centre = g.corner(v) + 0.5 * g.voxel;
        const int side = glm::dot(centre - p.centroid, p.normal) > 0.0 ? 0 : 1;
        const double d = glm::length(centre - start);
        if (d < nearest[side]) {
          nearest[side] = d;
          found[side] = l;
        }
      }
  return nearest[0] < kInf ? found[0] : found[1];
}

// Each patch's cell: the voxel ahead of it; else that of the nearest patch of its own polygon
// whose voxel ahead was free (the same surface, a little further from the wall it runs into);
// else the nearest cell.
std::vector<int> cellsFaced(const Grid& g, const Labels& labels, const Polygons& polys,
                            const std::vector<Patch>& patches, int reach) {
  std::vector<int> out(patches.size());
  std::vector<std::vector<int>> seen(polys.bounds.size());  // per polygon, its patches with a label
  for (size_t i = 0; i < patches.size(); ++i) {
    out[i] = labelAhead(g, labels, polys, patches[i]);
    if (out[i] != kUnreached) seen[patches[i].polygon].push_back(int(i));
  }
  for (size_t i = 0; i < patches.size(); ++i) {
    if (out[i] != kUnreached) continue;
    const std::vector<int>& same = seen[patches[i].polygon];
    int best = -1;
    for (int j : same)
      if (best < 0 || glm::length(patches[j].centroid - patches[i].centroid) <
                          glm::length(patches[best].centroid - patches[i].centroid))
        best = j;
    out[i] = best >= 0 ? out[best] : nearestCell(g, labels, patches[i], reach);
  }
  return out;
}

}  // namespace

std::string groupOfOrigin(const std::string& origin) {
  for (const std::string& key : {std::string("room '"), std::string("(object '")}) {
    const auto at = origin.find(key);
    if (at == std::string::npos) continue;
    const auto begin = at + key.size();
    const auto end = origin.find_first_of("'/", begin);
    if (end != std::string::npos && end > begin) return origin.substr(begin, end - begin);
  }
  return "";
}

CellPartition findCells(const Scene& scene, const std::vector<Patch>& patches) {
  CellPartition out;
  if (patches.empty()) return out;
  int pad = 0;
  const Grid g = makeGrid(patches, pad);
  const int radius = pad - 2;
  const Labels labels = labelVoxels(g, voxelise(g, patches), radius);

  const int cells = std::max(labels.cells, 1);  // no enclosed room at all: the whole scene is one
  const Polygons polys(scene);
  out.cellOfPatch = labels.cells == 0 ? std::vector<int>(patches.size(), 0)
                                       : cellsFaced(g, labels, polys, patches, 2 * radius);
  if (labels.cells > 0) out.portals = findPortals(g, labels, polys, radius);

  out.cells.resize(cells);
  std::vector<Vec3> lo(cells, Vec3(kInf)), hi(cells, Vec3(-kInf));
  long i = 0;
  for (int z = 0; z < g.n[2]; ++z)
    for (int y = 0; y < g.n[1]; ++y)
      for (int x = 0; x < g.n[0]; ++x, ++i) {
        const std::int32_t l = labels.label[i];
        if (l < 0) continue;
        const Vec3 corner = g.corner({x, y, z});
        lo[l] = glm::min(lo[l], corner);
        hi[l] = glm::max(hi[l], corner + g.voxel);
      }
  // Names: the group (room, MGF object) holding most of a cell's patch area, else "cell N".
  std::vector<std::map<std::string, double>> groupArea(cells);
  for (size_t i = 0; i < patches.size(); ++i) {
    const int c = out.cellOfPatch[i];
    const std::string group = groupOfOrigin(scene.polygons[patches[i].polygon].origin);
    if (c >= 0 && !group.empty()) groupArea[c][group] += patches[i].areaM2;
  }
  std::map<std::string, int> used;
  for (int c = 0; c < cells; ++c) {
    std::string name;
    double most = 0.0;
    for (const auto& [group, area] : groupArea[c])
      if (area > most) {
        most = area;
        name = group;
      }
    if (name.empty() || used[name]++ > 0) name = "cell " + std::to_string(c);
    Cell& cell = out.cells[c];
    cell.name = name;
    if (labels.cells == 0) std::tie(lo[0], hi[0]) = boundsOf(patches);  // the scene's bounds
    cell.boundsMin = lo[c];
    cell.boundsMax = hi[c];
  }
  return out;
}

}  // namespace radmesh
