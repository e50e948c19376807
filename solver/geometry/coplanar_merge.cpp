#include "solver/geometry/coplanar_merge.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

#include "solver/geometry/edge_key.h"

namespace radmesh {

namespace {

// Tolerances relative to the scene's size, so that the same model in millimetres or kilometres
// merges alike. Tight on purpose: a missed merge costs a few extra patches, a wrong one bends a wall.
constexpr double kWeldRelative = 1e-7;
constexpr double kPlaneDistanceRelative = 1e-6;
constexpr double kPlaneAngleRad = 1e-4;
constexpr double kCollinearSine = 1e-7;
// A triangle thinner than this (area / longest edge^2) has no area worth solving.
constexpr double kDegenerateAreaRatio = 1e-10;
// A model spans at most this many of its typical triangles, as far as the tolerances are concerned.
constexpr double kExtentPerMedianEdge = 1000.0;

bool isMergeable(const Polygon& p) {
  return p.vertices.size() == 3 && std::all_of(p.vertices.begin(), p.vertices.end(), isFinite);
}

// Welds positions that coincide within a tolerance: a hash grid with cells of the tolerance's
// size, searched in the 27 cells around a point. The first position seen stands for the rest.
class VertexWelder {
 public:
  explicit VertexWelder(double tolerance) : tolerance_(tolerance) {}

  int id(const Vec3& p) {
    const std::array<int64_t, 3> cell = cellOf(p);
    int best = -1;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          auto it = cells_.find(key({cell[0] + dx, cell[1] + dy, cell[2] + dz}));
          if (it == cells_.end()) continue;
          for (int candidate : it->second)
            if (glm::length(positions_[candidate] - p) <= tolerance_ && (best < 0 || candidate < best))
              best = candidate;
        }
    if (best >= 0) return best;
    positions_.push_back(p);
    const int created = static_cast<int>(positions_.size()) - 1;
    cells_[key(cell)].push_back(created);
    return created;
  }

  const Vec3& position(int id) const { return positions_[id]; }

 private:
  std::array<int64_t, 3> cellOf(const Vec3& p) const {
    return {static_cast<int64_t>(std::floor(p.x / tolerance_)),
            static_cast<int64_t>(std::floor(p.y / tolerance_)),
            static_cast<int64_t>(std::floor(p.z / tolerance_))};
  }
  static uint64_t key(const std::array<int64_t, 3>& c) {
    uint64_t h = 1469598103934665603ull;  // FNV-1a over the three cell coordinates
    for (int64_t v : c) h = (h ^ static_cast<uint64_t>(v)) * 1099511628211ull;
    return h;
  }

  double tolerance_;
  std::vector<Vec3> positions_;
  std::unordered_map<uint64_t, std::vector<int>> cells_;
};

struct Triangle {
  std::array<int, 3> corner;  // welded vertex ids, counter-clockwise
  Vec3 normal;                // unit
  int material;
  size_t source;  // index into the input
};

// The length the tolerances are relative to: the diagonal of the bounding box of the mergeable
// triangles (1 when there is none), but no more than a thousand times their median longest edge.
// One stray triangle far away (or one vertex at 3e38) would otherwise stretch the box until the
// weld joined every corner of the model: rounding grows with the coordinates, not with the box.
double sceneExtent(const std::vector<Polygon>& input) {
  bool any = false;
  Vec3 lo{0.0}, hi{0.0};
  std::vector<double> longest;
  for (const Polygon& p : input)
    if (isMergeable(p)) {
      for (const Vec3& v : p.vertices) {
        lo = any ? glm::min(lo, v) : v;
        hi = any ? glm::max(hi, v) : v;
        any = true;
      }
      const auto& v = p.vertices;
      longest.push_back(std::max({glm::length(v[1] - v[0]), glm::length(v[2] - v[1]), glm::length(v[0] - v[2])}));
    }
  double extent = glm::length(hi - lo);
  if (!longest.empty()) {
    std::nth_element(longest.begin(), longest.begin() + longest.size() / 2, longest.end());
    const double median = longest[longest.size() / 2];
    if (median > 0.0 && std::isfinite(median)) extent = std::min(extent, kExtentPerMedianEdge * median);
  }
  return extent > 0.0 && std::isfinite(extent) ? extent : 1.0;
}

// A region grown from one triangle; it stays a topological disk, so its boundary is one loop.
struct Region {
  std::unordered_set<uint64_t> boundary;  // directed edges, counter-clockwise
  std::unordered_set<int> vertices;
};

class RegionMerger {
 public:
  RegionMerger(const std::vector<Polygon>& input, MergeReport& report)
      : input_(input),
        report_(report),
        extent_(sceneExtent(input)),
        planeTolerance_(kPlaneDistanceRelative * extent_),
        welder_(kWeldRelative * extent_) {
    buildTriangles();
  }

  std::vector<Polygon> run() {
    std::vector<Polygon> out;
    std::vector<int> triangleOfInput(input_.size(), -1);
    for (size_t t = 0; t < triangles_.size(); ++t) triangleOfInput[triangles_[t].source] = static_cast<int>(t);
    for (size_t i = 0; i < input_.size(); ++i) {
      if (!isMergeable(input_[i])) {
        out.push_back(input_[i]);
        continue;
      }
      const int t = triangleOfInput[i];
      if (t < 0 || assigned_[t]) continue;  // dropped as degenerate, or already in a region
      out.push_back(grow(t));
    }
    report_.polygonsOut = out.size();
    return out;
  }

 private:
  void buildTriangles() {
    for (size_t i = 0; i < input_.size(); ++i) {
      const Polygon& p = input_[i];
      if (!isMergeable(p)) continue;
      ++report_.trianglesIn;
      Triangle t{{welder_.id(p.vertices[0]), welder_.id(p.vertices[1]), welder_.id(p.vertices[2])},
                 Vec3{0.0}, p.material, i};
      const Vec3 a = welder_.position(t.corner[0]), b = welder_.position(t.corner[1]),
                 c = welder_.position(t.corner[2]);
      const Vec3 n = glm::cross(b - a, c - a);
      const double longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
      const bool repeated = t.corner[0] == t.corner[1] || t.corner[1] == t.corner[2] || t.corner[0] == t.corner[2];
      if (repeated || !(0.5 * glm::length(n) > kDegenerateAreaRatio * longest * longest)) {
        ++report_.degenerateDropped;
        continue;
      }
      t.normal = glm::normalize(n);
      const int id = static_cast<int>(triangles_.size());
      for (int e = 0; e < 3; ++e) {
        const int from = t.corner[e], to = t.corner[(e + 1) % 3];
        edges_[directedEdgeKey(std::min(from, to), std::max(from, to))].push_back(id);
      }
      triangles_.push_back(t);
    }
    assigned_.assign(triangles_.size(), false);
  }

  // The triangle across edge e of t, when exactly two triangles share that edge with opposite
  // windings (a manifold, consistently oriented edge); -1 otherwise.
  int across(int t, int e) const {
    const int from = triangles_[t].corner[e], to = triangles_[t].corner[(e + 1) % 3];
    const std::vector<int>& sharing = edges_.at(directedEdgeKey(std::min(from, to), std::max(from, to)));
    if (sharing.size() != 2) return -1;
    const int other = sharing[0] == t ? sharing[1] : sharing[0];
    const auto& c = triangles_[other].corner;
    for (int k = 0; k < 3; ++k)
      if (c[k] == to && c[(k + 1) % 3] == from) return other;
    return -1;
  }

  bool samePlaneAndMaterial(const Triangle& seed, const Triangle& t) const {
    if (t.material != seed.material || glm::dot(t.normal, seed.normal) < std::cos(kPlaneAngleRad)) return false;
    const Vec3 origin = welder_.position(seed.corner[0]);
    for (int v : t.corner)
      if (std::abs(glm::dot(welder_.position(v) - origin, seed.normal)) > planeTolerance_) return false;
    return true;
  }

  // Adding t keeps the region a disk when t meets its boundary along one edge with its third
  // corner new to the region, or along two (necessarily consecutive) edges.
  static bool keepsDisk(const Region& r, const Triangle& t) {
    int shared = 0, opposite = -1;
    for (int e = 0; e < 3; ++e) {
      const int from = t.corner[e], to = t.corner[(e + 1) % 3];
      if (r.boundary.count(directedEdgeKey(to, from))) {
        ++shared;
        opposite = t.corner[(e + 2) % 3];
      }
    }
    if (shared == 1) return r.vertices.count(opposite) == 0;
    return shared == 2;
  }

  static void add(Region& r, const Triangle& t) {
    for (int e = 0; e < 3; ++e) {
      const int from = t.corner[e], to = t.corner[(e + 1) % 3];
      if (!r.boundary.erase(directedEdgeKey(to, from))) r.boundary.insert(directedEdgeKey(from, to));
      r.vertices.insert(from);
    }
  }

  Polygon grow(int seed) {
    Region region;
    add(region, triangles_[seed]);
    assigned_[seed] = true;
    std::deque<int> pending;
    auto pushNeighbours = [&](int t) {
      for (int e = 0; e < 3; ++e) {
        const int n = across(t, e);
        if (n >= 0 && !assigned_[n] && samePlaneAndMaterial(triangles_[seed], triangles_[n])) pending.push_back(n);
      }
    };
    pushNeighbours(seed);
    // A triangle refused now may fit later, once a second neighbour joins; that neighbour's
    // joining pushes it again.
    while (!pending.empty()) {
      const int t = pending.front();
      pending.pop_front();
      if (assigned_[t] || !keepsDisk(region, triangles_[t])) continue;
      add(region, triangles_[t]);
      assigned_[t] = true;
      pushNeighbours(t);
    }
    const Polygon& first = input_[triangles_[seed].source];
    return Polygon{outline(region), first.material, first.origin};
  }

  bool collinear(int a, int b, int c) const {
    const Vec3 u = welder_.position(b) - welder_.position(a);
    const Vec3 w = welder_.position(c) - welder_.position(b);
    return glm::dot(u, w) > 0.0 &&
           glm::length(glm::cross(u, w)) <= kCollinearSine * glm::length(u) * glm::length(w);
  }

  // The boundary loop in order, from its lowest-numbered vertex (or the first corner after it, so
  // a quad given as two triangles comes back vertex for vertex), without the vertices that lie in
  // the middle of straight edges.
  std::vector<Vec3> outline(const Region& r) const {
    std::unordered_map<int, int> next;
    for (uint64_t e : r.boundary) next[static_cast<int>(e >> 32)] = static_cast<int>(e & 0xffffffffu);
    std::vector<int> loop;
    int start = next.begin()->first;
    for (const auto& [from, to] : next) start = std::min(start, from);
    for (int v = start; loop.empty() || v != start; v = next.at(v)) {
      loop.push_back(v);
      if (loop.size() > next.size()) throw std::logic_error("coplanar merge: region boundary is not one loop");
    }
    const size_t n = loop.size();
    size_t first = 0;
    while (first < n && collinear(loop[(first + n - 1) % n], loop[first], loop[(first + 1) % n])) ++first;
    if (first == n) throw std::logic_error("coplanar merge: region without a corner");
    std::vector<Vec3> vertices;
    int kept = loop[first];
    vertices.push_back(welder_.position(kept));
    for (size_t k = 1; k < n; ++k) {
      const int v = loop[(first + k) % n], after = loop[(first + k + 1) % n];
      if (collinear(kept, v, after)) continue;
      vertices.push_back(welder_.position(v));
      kept = v;
    }
    return vertices;
  }

  const std::vector<Polygon>& input_;
  MergeReport& report_;
  double extent_;
  double planeTolerance_;
  VertexWelder welder_;
  std::vector<Triangle> triangles_;
  std::vector<bool> assigned_;
  std::unordered_map<uint64_t, std::vector<int>> edges_;  // undirected edge -> triangles on it
};

}  // namespace

std::vector<Polygon> mergeCoplanarTriangles(const std::vector<Polygon>& triangles, MergeReport* report) {
  MergeReport local;
  MergeReport& r = report ? *report : local;
  r = MergeReport{};
  return RegionMerger(triangles, r).run();
}

}  // namespace radmesh
