#include "solver/geometry/openings.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "solver/geometry/point_grid.h"
#include "solver/geometry/polygon_3d.h"
#include "solver/geometry/polygon_triangulate.h"

namespace radmesh {

namespace {

// An edge's supporting line, canonical up to sign, in steps of a tolerance: its direction (steps of
// 1e-6) and its point nearest `centre` (steps of the tolerance), the scene's middle, so that site
// coordinates do not magnify the rounding of the direction into the point.
using LineCoordinates = std::array<double, 6>;
using LineKey = std::array<long long, 6>;

LineCoordinates lineCoordinates(const Vec3& a, const Vec3& b, const Vec3& centre, double tolerance) {
  Vec3 d = glm::normalize(b - a);
  // The sign of the first component well clear of 0, which rounding cannot flip.
  const int k = std::abs(d.x) > 0.3 ? 0 : std::abs(d.y) > 0.3 ? 1 : 2;
  if (d[k] < 0.0) d = -d;
  const Vec3 foot = (a - centre) - glm::dot(a - centre, d) * d;
  return {d.x / 1e-6, d.y / 1e-6, d.z / 1e-6, foot.x / tolerance, foot.y / tolerance, foot.z / tolerance};
}

LineKey lineKey(const LineCoordinates& c) {
  LineKey key;
  for (size_t i = 0; i < c.size(); ++i) key[i] = std::llround(c[i]);
  return key;
}

// The keys of every line within a quarter step of these coordinates: a collinear edge whose
// rounding carried it across a step's boundary is in one of them.
std::vector<LineKey> nearKeys(const LineCoordinates& c) {
  std::vector<LineKey> keys{LineKey{}};
  for (size_t i = 0; i < c.size(); ++i) {
    const long long low = std::llround(c[i] - 0.25), high = std::llround(c[i] + 0.25);
    const size_t n = keys.size();
    for (size_t k = 0; k < n; ++k) {
      keys[k][i] = low;
      if (high != low) {
        keys.push_back(keys[k]);
        keys.back()[i] = high;
      }
    }
  }
  return keys;
}

// Points within a tolerance of one another get one index (the first such point stands for all).
class Welder {
 public:
  explicit Welder(double tolerance) : tolerance_(tolerance) {}
  int id(const Vec3& p) {
    const Cell c = cellOf(p);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          const auto found = cells_.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (found == cells_.end()) continue;
          for (int i : found->second)
            if (glm::length(points_[i] - p) <= tolerance_) return i;
        }
    points_.push_back(p);
    cells_[c].push_back(static_cast<int>(points_.size() - 1));
    return static_cast<int>(points_.size() - 1);
  }
  const Vec3& point(int id) const { return points_[id]; }

 private:
  using Cell = std::array<long long, 3>;
  Cell cellOf(const Vec3& p) const {
    return {std::llround(p.x / tolerance_), std::llround(p.y / tolerance_), std::llround(p.z / tolerance_)};
  }
  double tolerance_;
  std::vector<Vec3> points_;
  std::map<Cell, std::vector<int>> cells_;
};

// Whether a stretch of edge lies on another polygon's face (in its plane, inside it): a column or a
// partition wall standing on a floor that runs on past it. The face seals it; no light leaves there.
// Three points along it are tested, each on any face, so a floor in pieces seals it too.
class FaceSeal {
 public:
  FaceSeal(const Scene& scene, double tolerance)
      : scene_(scene), tolerance_(tolerance), faces_(std::max(sceneDiagonal(scene) / kBucketsAcross, 1e-9)) {
    for (size_t f = 0; f < scene.polygons.size(); ++f) {
      Vec3 low(INFINITY), high(-INFINITY);
      for (const Vec3& v : scene.polygons[f].vertices) low = glm::min(low, v), high = glm::max(high, v);
      const Vec3 n = newellNormal(scene.polygons[f].vertices);
      const double length = glm::length(n);
      normals_.push_back(length > 0.0 ? n / length : Vec3(0.0));
      if (length > 0.0) faces_.insert(low - tolerance, high + tolerance, static_cast<int>(f));
    }
  }
  bool seals(const BoundarySegment& s) const {
    return std::all_of(kAlong.begin(), kAlong.end(),
                       [&](double t) { return onAFace(s.a + t * (s.b - s.a), s.polygon); });
  }

 private:
  static constexpr std::array<double, 3> kAlong{0.25, 0.5, 0.75};
  static constexpr double kBucketsAcross = 64.0;  // of the scene's diagonal
  // On a face other than `own`, inside it and clear of its edges (on an edge, the edges decide).
  bool onAFace(const Vec3& point, size_t own) const {
    return faces_.anyInBox(point, point, [&](int f) {
      const std::vector<Vec3>& v = scene_.polygons[f].vertices;
      const Vec3& normal = normals_[f];
      if (static_cast<size_t>(f) == own || !(std::abs(glm::dot(point - v[0], normal)) <= tolerance_) ||
          !insidePolygon(v, normal, point))
        return false;
      for (size_t k = 0; k < v.size(); ++k) {
        const Vec3 a = v[k], d = v[(k + 1) % v.size()] - a;
        const double t = std::clamp(glm::dot(point - a, d) / std::max(glm::dot(d, d), 1e-300), 0.0, 1.0);
        if (!(glm::length(point - (a + t * d)) > tolerance_)) return false;
      }
      return true;
    });
  }
  const Scene& scene_;
  double tolerance_;
  std::vector<Vec3> normals_;
  PointGrid faces_;
};

std::string describeLoop(const std::vector<Vec3>& loop) {
  Vec3 mean(0.0);
  for (const Vec3& v : loop) mean += v;
  mean /= double(loop.size());
  return fmt::format("the boundary loop of {} edges around ({:.4g}, {:.4g}, {:.4g})", loop.size(), mean.x, mean.y,
                     mean.z);
}

// Drops every vertex that lies on the line through its neighbours: a wall cut into pieces leaves
// several collinear edges along one side of a window.
std::vector<Vec3> mergeCollinear(std::vector<Vec3> loop, double tolerance) {
  for (bool changed = true; changed && loop.size() > 3;) {
    changed = false;
    for (size_t i = 0; i < loop.size() && loop.size() > 3; ++i) {
      const Vec3& prev = loop[(i + loop.size() - 1) % loop.size()];
      const Vec3& next = loop[(i + 1) % loop.size()];
      const Vec3 d = next - prev;
      const double off = glm::length(glm::cross(loop[i] - prev, d)) / std::max(glm::length(d), tolerance);
      if (off <= tolerance) loop.erase(loop.begin() + static_cast<std::ptrdiff_t>(i)), changed = true;
    }
  }
  return loop;
}

// A point inside a planar loop: the centroid of its largest triangle (the loop may be concave).
bool insidePoint(const std::vector<Vec3>& loop, const Vec3& normal, double tolerance, Vec3& inside) {
  const auto [u, v] = dominantPlane(normal);
  std::vector<Vec2> flat;
  for (const Vec3& p : loop) flat.emplace_back(p[u], p[v]);
  const bool reversed = signedArea(flat) < 0.0;
  if (reversed) std::reverse(flat.begin(), flat.end());
  double best = 0.0;
  for (const auto& t : triangulatePolygon(flat, tolerance)) {
    const double area = cross2(flat[t[1]] - flat[t[0]], flat[t[2]] - flat[t[0]]);
    if (area <= best) continue;
    best = area;
    inside = Vec3(0.0);
    for (int k : t) inside += loop[reversed ? loop.size() - 1 - size_t(k) : size_t(k)] / 3.0;
  }
  return best > 0.0;
}

}  // namespace

double sceneDiagonal(const Scene& scene) {
  const auto [low, high] = boundingBox(scene.polygons);
  return scene.polygons.empty() ? 0.0 : glm::length(high - low);
}

std::vector<BoundarySegment> boundarySegments(const Scene& scene, double tolerance) {
  const auto [low, high] = boundingBox(scene.polygons);
  const Vec3 centre = (low + high) / 2.0;
  struct Line {
    std::vector<BoundarySegment> edges;
    std::vector<LineCoordinates> coordinates;  // each edge's own
  };
  std::map<LineKey, Line> lines;
  for (size_t p = 0; p < scene.polygons.size(); ++p) {
    const auto& v = scene.polygons[p].vertices;
    for (size_t k = 0; k < v.size(); ++k) {
      const Vec3 a = v[k], b = v[(k + 1) % v.size()];
      if (!(glm::length(b - a) > tolerance)) continue;
      const LineCoordinates c = lineCoordinates(a, b, centre, tolerance);
      Line& line = lines[lineKey(c)];
      line.edges.push_back({a, b, p});
      line.coordinates.push_back(c);
    }
  }
  std::vector<BoundarySegment> open;
  const FaceSeal faces(scene, tolerance);
  for (const auto& [key, line] : lines) {
    for (size_t i = 0; i < line.edges.size(); ++i) {
      const BoundarySegment& e = line.edges[i];
      const Vec3 d = glm::normalize(e.b - e.a);
      const double length = glm::length(e.b - e.a);
      auto at = [&](double s) { return s <= 0.0 ? e.a : s >= length ? e.b : e.a + s * d; };
      // What the edges of a line cover of e (but e itself), then what they leave uncovered.
      std::vector<std::pair<double, double>> cover;
      const auto gather = [&](const Line& other) {
        for (const BoundarySegment& f : other.edges) {
          if (&f == &e) continue;
          double s = glm::dot(f.a - e.a, d), t = glm::dot(f.b - e.a, d);
          if (s > t) std::swap(s, t);
          cover.emplace_back(s, t);
        }
      };
      const auto uncovered = [&] {
        std::sort(cover.begin(), cover.end());
        std::vector<BoundarySegment> left;
        double reached = 0.0;
        for (const auto& [s, t] : cover) {
          if (reached >= length - tolerance) break;
          if (s > reached + tolerance) left.push_back({at(reached), at(std::min(s, length)), e.polygon});
          reached = std::max(reached, t);
        }
        if (reached < length - tolerance) left.push_back({at(reached), e.b, e.polygon});
        return left;
      };
      // Its own line's edges cover most edges; the lines a quarter step away only the rest.
      gather(line);
      std::vector<BoundarySegment> left = uncovered();
      if (!left.empty()) {
        for (const LineKey& near : nearKeys(line.coordinates[i]))
          if (const auto found = lines.find(near); near != key && found != lines.end()) gather(found->second);
        left = uncovered();
      }
      for (const BoundarySegment& stretch : left)
        if (!faces.seals(stretch)) open.push_back(stretch);
    }
  }
  return open;
}

OpeningSearch findOpenings(const Scene& scene) {
  const double tolerance = 1e-7 * sceneDiagonal(scene);
  const std::vector<BoundarySegment> segments = boundarySegments(scene, tolerance);
  Welder welder(tolerance);
  std::vector<std::pair<int, int>> ends;  // welded start and end of each segment
  std::map<int, std::vector<size_t>> leaving;
  for (size_t s = 0; s < segments.size(); ++s) {
    ends.emplace_back(welder.id(segments[s].a), welder.id(segments[s].b));
    leaving[ends.back().first].push_back(s);
  }
  OpeningSearch search;
  std::vector<bool> used(segments.size(), false);
  for (size_t first = 0; first < segments.size(); ++first) {
    if (used[first]) continue;
    std::vector<Vec3> loop;
    bool closed = false;
    for (size_t s = first;;) {
      used[s] = true;
      loop.push_back(welder.point(ends[s].first));
      if (ends[s].second == ends[first].first) {
        closed = true;
        break;
      }
      const auto next = leaving.find(ends[s].second);
      if (next == leaving.end()) break;
      const auto free = std::find_if(next->second.begin(), next->second.end(), [&](size_t n) { return !used[n]; });
      if (free == next->second.end()) break;
      s = *free;
    }
    if (!closed) {
      search.skipped.add("open", describeLoop(loop) + " does not close: it is not an opening");
      continue;
    }
    // The loop runs as its polygons' edges do, around the hole clockwise seen from their front.
    std::reverse(loop.begin(), loop.end());
    loop = mergeCollinear(std::move(loop), tolerance);
    const Vec3 n = newellNormal(loop);
    const double area = 0.5 * glm::length(n);
    double extent = 0.0, off = 0.0;
    for (const Vec3& v : loop) extent = std::max(extent, glm::length(v - loop[0]));
    for (const Vec3& v : loop) off = std::max(off, area > 0.0 ? std::abs(glm::dot(v - loop[0], n / (2.0 * area))) : 0.0);
    Vec3 inside(0.0);
    if (loop.size() < 3 || !(area > 1e-12 * extent * extent) || !insidePoint(loop, n, tolerance, inside)) {
      search.skipped.add("no area", describeLoop(loop) + " encloses no area: it is not an opening");
    } else if (off > 1e-3 * extent) {
      search.skipped.add("bent", describeLoop(loop) + fmt::format(" is not planar (a vertex {:.3g} m off its plane): "
                                                                "not an opening; close it with a polygon", off));
    } else {
      search.openings.push_back({std::move(loop), inside});
    }
  }
  return search;
}

}  // namespace radmesh
