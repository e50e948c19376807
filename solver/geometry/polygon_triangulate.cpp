#include "solver/geometry/polygon_triangulate.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>

namespace radmesh {

namespace {

// The polygon's remaining vertices as a doubly linked ring over indices of the input.
class Ring {
 public:
  explicit Ring(int n) : prev_(n), next_(n), count_(n) {
    for (int i = 0; i < n; ++i) {
      prev_[i] = (i + n - 1) % n;
      next_[i] = (i + 1) % n;
    }
  }
  int prev(int i) const { return prev_[i]; }
  int next(int i) const { return next_[i]; }
  int count() const { return count_; }
  void remove(int i) {
    next_[prev_[i]] = next_[i];
    prev_[next_[i]] = prev_[i];
    --count_;
  }

 private:
  std::vector<int> prev_, next_;
  int count_;
};

// Per point, the first index of a point bitwise equal to it: one id for points no test can tell apart.
std::vector<int> samePointIds(const std::vector<Vec2>& p) {
  const auto bits = [&](int i) {
    return std::pair{std::bit_cast<std::uint64_t>(p[i].x), std::bit_cast<std::uint64_t>(p[i].y)};
  };
  std::vector<int> order(p.size()), id(p.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return bits(a) < bits(b); });
  for (size_t k = 0; k < order.size(); ++k)
    id[order[k]] = k > 0 && bits(order[k]) == bits(order[k - 1]) ? id[order[k - 1]] : order[k];
  return id;
}

// The ring's corners (a vertex's point with its neighbours' points, as samePointIds), each with how
// many vertices have it. Whether a vertex blocks an ear depends on its corner alone, so an outline
// that goes round the same points again and again (30 000 times round a triangle) is tested at its
// few distinct corners rather than at every vertex, each ear in constant time, not the ring's length.
class Corners {
 public:
  using Corner = std::array<int, 3>;  // previous, own, next
  void add(const Corner& corner) {
    const auto [at, added] = index_.try_emplace(corner, static_cast<int>(counted_.size()));
    if (added) counted_.push_back({corner, 0});
    ++counted_[at->second].second;
  }
  void remove(const Corner& corner) {
    const auto at = index_.find(corner);
    const int k = at->second;
    if (--counted_[k].second > 0) return;
    index_.erase(at);
    if (k + 1 < static_cast<int>(counted_.size())) index_[counted_.back().first] = k;
    counted_[k] = counted_.back();
    counted_.pop_back();
  }
  const std::vector<std::pair<Corner, int>>& counted() const { return counted_; }

 private:
  std::vector<std::pair<Corner, int>> counted_;  // distinct, in no order
  std::map<Corner, int> index_;                  // where each is in counted_
};

class EarClipper {
 public:
  EarClipper(const std::vector<Vec2>& points, double noiseM)
      : p_(points), noise_(noiseM), same_(samePointIds(points)), ring_(static_cast<int>(points.size())) {
    for (int i = 0; i < ring_.count(); ++i) corners_.add(cornerOf(i));
  }

  std::vector<std::array<int, 3>> run() {
    int i = 0;
    int stalled = 0;  // vertices visited since the last removal
    while (ring_.count() > 3) {
      if (degenerate(i) || (convex(i) && !blocked(i))) {
        // Revisit the neighbour next: removing a vertex can make it degenerate or an ear.
        const int neighbour = ring_.prev(i);
        if (!degenerate(i)) triangles_.push_back({neighbour, i, ring_.next(i)});
        remove(i);
        i = neighbour;
        stalled = 0;
      } else if (++stalled < ring_.count()) {
        i = ring_.next(i);
      } else {
        i = clipFirstConvex(i);
        if (i < 0) break;  // only reflex vertices left: the rest encloses no positive area
        stalled = 0;
      }
    }
    if (ring_.count() == 3 && !degenerate(i) && convex(i))
      triangles_.push_back({ring_.prev(i), i, ring_.next(i)});
    return std::move(triangles_);
  }

 private:
  Corners::Corner cornerOf(int i) const { return {same_[ring_.prev(i)], same_[i], same_[ring_.next(i)]}; }

  // Out of the ring, and its corner out of the count; its neighbours' corners change with it.
  void remove(int i) {
    const int prev = ring_.prev(i), next = ring_.next(i);
    for (int v : {prev, i, next}) corners_.remove(cornerOf(v));
    ring_.remove(i);
    for (int v : {prev, next}) corners_.add(cornerOf(v));
  }

  // b's distance from the chord ac: negative when a, b, c turn left (b is convex).
  double turn(int i) const { return sideOfLine(p_[ring_.prev(i)], p_[ring_.next(i)], p_[i]); }
  bool convex(int i) const { return turn(i) < -noise_; }

  // Collinear, repeated, or a zero-width spike: removing it changes no area.
  bool degenerate(int i) const {
    const Vec2 &a = p_[ring_.prev(i)], &b = p_[i], &c = p_[ring_.next(i)];
    if (glm::length(b - a) <= noise_ || glm::length(c - b) <= noise_ || glm::length(c - a) <= noise_)
      return true;
    return std::abs(turn(i)) <= noise_;
  }

  // Does polygon boundary reach into the interior of the triangle (prev, i, next)? In a weakly
  // simple polygon only a vertex can: one strictly inside, or one on the triangle's boundary
  // (e.g. the far end of a seam) with an edge leaving it into the interior. Each distinct corner
  // of the other vertices is asked once.
  bool blocked(int i) const {
    const int ia = ring_.prev(i), ic = ring_.next(i);
    const std::array<Vec2, 3> t{p_[ia], p_[i], p_[ic]};
    const Vec2 lo = glm::min(t[0], glm::min(t[1], t[2])) - noise_;
    const Vec2 hi = glm::max(t[0], glm::max(t[1], t[2])) + noise_;
    const std::array<Corners::Corner, 3> own{cornerOf(ia), cornerOf(i), cornerOf(ic)};
    for (const auto& [corner, count] : corners_.counted()) {
      const Vec2& q = p_[corner[1]];
      if (q.x < lo.x || q.y < lo.y || q.x > hi.x || q.y > hi.y) continue;
      if (count > std::count(own.begin(), own.end(), corner) && blocks(t, q, p_[corner[0]], p_[corner[2]]))
        return true;
    }
    return false;
  }

  // Whether a vertex at q, its neighbours at prev and next, reaches into the triangle t.
  bool blocks(const std::array<Vec2, 3>& t, const Vec2& q, const Vec2& prev, const Vec2& next) const {
    std::array<double, 3> side;
    for (int s = 0; s < 3; ++s) side[s] = sideOfLine(t[s], t[(s + 1) % 3], q);
    if (*std::min_element(side.begin(), side.end()) < -noise_) return false;
    if (*std::min_element(side.begin(), side.end()) > noise_) return true;
    return entersTriangle(t, side, q, prev) || entersTriangle(t, side, q, next);
  }

  // An edge q->r, with q on the triangle's boundary, enters its interior when it points to the
  // inner side of every triangle side q lies on.
  bool entersTriangle(const std::array<Vec2, 3>& t, const std::array<double, 3>& side, const Vec2& q,
                      const Vec2& r) const {
    const double length = glm::length(r - q);
    if (length <= noise_) return false;
    const Vec2 d = (r - q) / length;
    for (int s = 0; s < 3; ++s) {
      if (std::abs(side[s]) > noise_) continue;
      const Vec2 edge = t[(s + 1) % 3] - t[s];
      if (!(cross2(edge / glm::length(edge), d) > 1e-9)) return false;
    }
    return true;
  }

  // Rounding can hide every ear of a nearly degenerate remainder; clipping a convex vertex keeps
  // the loop finite, and the caller's area check reports a polygon this made wrong. Returns the
  // clipped vertex's neighbour, or -1 when no vertex is convex.
  int clipFirstConvex(int i) {
    for (int k = 0; k < ring_.count(); ++k, i = ring_.next(i)) {
      if (convex(i)) {
        const int neighbour = ring_.prev(i);
        triangles_.push_back({neighbour, i, ring_.next(i)});
        remove(i);
        return neighbour;
      }
    }
    return -1;
  }

  const std::vector<Vec2>& p_;
  double noise_;
  std::vector<int> same_;  // samePointIds(p_)
  Ring ring_;
  Corners corners_;
  std::vector<std::array<int, 3>> triangles_;
};

}  // namespace

std::vector<std::array<int, 3>> triangulatePolygon(const std::vector<Vec2>& ccw, double noiseM) {
  if (ccw.size() < 3) return {};
  return EarClipper(ccw, noiseM).run();
}

}  // namespace radmesh
