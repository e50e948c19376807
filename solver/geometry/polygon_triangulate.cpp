#include "solver/geometry/polygon_triangulate.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <utility>

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
// few distinct corners rather than at every vertex. The corners lie in a grid of square cells by
// their own point, and an ear asks only the cells its triangle meets: an ear spanning a convex
// remainder (a fan) meets a strip of cells, not the remainder's every corner: a 30 000-vertex star
// is clipped in 70 ms, where asking every corner took 550 ms (bench/geometry_bench.cpp).
class Corners {
 public:
  using Corner = std::array<int, 3>;  // previous, own, next

  // About one cell per distinct point, over the box of `points`.
  Corners(const std::vector<Vec2>& points, int distinctPoints) : p_(points) {
    Vec2 hi = lo_ = points[0];
    for (const Vec2& q : points) {
      lo_ = glm::min(lo_, q);
      hi = glm::max(hi, q);
    }
    const Vec2 size = hi - lo_;
    const int n = std::max(distinctPoints, 1);
    // Square cells of the box's area over n, but no smaller than its longer side over n: a thin box
    // gets a row of at most n + 1 of them, not n² tiny ones.
    cell_ = std::max(std::sqrt(size.x * size.y / n), std::max(size.x, size.y) / n);
    if (!(cell_ > 0.0)) cell_ = 1.0;  // every point the same
    const auto across = [&](double extent) { return extent / cell_ < n ? static_cast<int>(extent / cell_) + 1 : n + 1; };
    columns_ = across(size.x);
    rows_ = across(size.y);
    cells_.resize(static_cast<size_t>(columns_) * rows_);
  }

  void add(const Corner& corner) {
    const auto [at, added] = where_.try_emplace(corner);
    if (added) {
      auto& cell = cells_[cellOf(p_[corner[1]])];
      at->second = Slot{&cell, cell.size()};
      cell.push_back({corner, 0});
    }
    ++(*at->second.cell)[at->second.index].second;
  }

  void remove(const Corner& corner) {
    const auto at = where_.find(corner);
    auto& [cell, index] = at->second;
    if (--(*cell)[index].second > 0) return;
    if (index + 1 < cell->size()) {
      (*cell)[index] = cell->back();
      where_.find((*cell)[index].first)->second.index = index;
    }
    cell->pop_back();
    where_.erase(at);
  }

  // Calls visit(corner, count) for every corner whose point lies within `margin` of the triangle t
  // and in the box lo..hi (and for some others near it), until one returns true. Returns whether
  // one did.
  template <class Visit>
  bool anyNear(const std::array<Vec2, 3>& t, double margin, const Vec2& lo, const Vec2& hi, Visit&& visit) const {
    const double inf = std::numeric_limits<double>::infinity();
    const int rowLo = rowOf(lo.y), rowHi = rowOf(hi.y);
    for (int row = rowLo; row <= rowHi; ++row) {
      // The row's slab; the grid's first and last rows also hold the points beyond it.
      const double y0 = row == 0 ? -inf : lo_.y + row * cell_;
      const double y1 = row == rows_ - 1 ? inf : lo_.y + (row + 1) * cell_;
      const auto [x0, x1] = xExtent(t, y0 - margin, y1 + margin);
      if (x0 > x1) continue;
      const int columnHi = columnOf(std::min(x1 + margin, hi.x));
      for (int column = columnOf(std::max(x0 - margin, lo.x)); column <= columnHi; ++column)
        for (const auto& [corner, count] : cells_[static_cast<size_t>(row) * columns_ + column])
          if (visit(corner, count)) return true;
    }
    return false;
  }

 private:
  // Where the triangle meets the horizontal slab ya..yb, in x: its corners in the slab and its edges'
  // crossings of the slab's lines. Empty (first > second) where it misses the slab.
  static std::pair<double, double> xExtent(const std::array<Vec2, 3>& t, double ya, double yb) {
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0;
    const auto take = [&](double x) {
      x0 = std::min(x0, x);
      x1 = std::max(x1, x);
    };
    for (int s = 0; s < 3; ++s) {
      const Vec2 &a = t[s], &b = t[(s + 1) % 3];
      if (a.y >= ya && a.y <= yb) take(a.x);
      for (double y : {ya, yb})
        if (y > std::min(a.y, b.y) && y < std::max(a.y, b.y)) take(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
    }
    return {x0, x1};
  }

  int clampedCell(double offset, int cells) const {
    const double k = std::floor(offset / cell_);
    return k < 0.0 ? 0 : k >= cells - 1 ? cells - 1 : static_cast<int>(k);
  }
  int columnOf(double x) const { return clampedCell(x - lo_.x, columns_); }
  int rowOf(double y) const { return clampedCell(y - lo_.y, rows_); }
  size_t cellOf(const Vec2& q) const { return static_cast<size_t>(rowOf(q.y)) * columns_ + columnOf(q.x); }

  using Cell = std::vector<std::pair<Corner, int>>;  // distinct corners, in no order, with counts
  struct Slot {
    Cell* cell;
    size_t index;
  };
  struct CornerHash {
    size_t operator()(const Corner& c) const {
      const auto u = [](int v) { return static_cast<std::uint64_t>(static_cast<std::uint32_t>(v)); };
      return std::hash<std::uint64_t>()((u(c[0]) * 0x9E3779B97F4A7C15ull ^ u(c[1])) * 0x9E3779B97F4A7C15ull ^ u(c[2]));
    }
  };

  const std::vector<Vec2>& p_;
  Vec2 lo_;
  double cell_;
  int columns_, rows_;
  std::vector<Cell> cells_;                             // row by row
  std::unordered_map<Corner, Slot, CornerHash> where_;  // where each corner is in cells_
};

// How many distinct points samePointIds found.
int distinctCount(const std::vector<int>& same) {
  int n = 0;
  for (size_t i = 0; i < same.size(); ++i) n += same[i] == static_cast<int>(i);
  return n;
}

class EarClipper {
 public:
  EarClipper(const std::vector<Vec2>& points, double noiseM)
      : p_(points),
        noise_(noiseM),
        same_(samePointIds(points)),
        ring_(static_cast<int>(points.size())),
        corners_(points, distinctCount(same_)) {
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
  // of the other vertices near the triangle is asked once.
  bool blocked(int i) const {
    const int ia = ring_.prev(i), ic = ring_.next(i);
    const std::array<Vec2, 3> t{p_[ia], p_[i], p_[ic]};
    const Vec2 lo = glm::min(t[0], glm::min(t[1], t[2])) - noise_;
    const Vec2 hi = glm::max(t[0], glm::max(t[1], t[2])) + noise_;
    const std::array<Corners::Corner, 3> own{cornerOf(ia), cornerOf(i), cornerOf(ic)};
    return corners_.anyNear(t, reach(t), lo, hi, [&](const Corners::Corner& corner, int count) {
      const Vec2& q = p_[corner[1]];
      if (q.x < lo.x || q.y < lo.y || q.x > hi.x || q.y > hi.y) return false;
      return count > std::count(own.begin(), own.end(), corner) && blocks(t, q, p_[corner[0]], p_[corner[2]]);
    });
  }

  // How far beyond the triangle a point blocks may reach: blocks takes points up to noise_ outside
  // each side, and where two sides meet at an angle theta those offsets meet noise_ / sin(theta / 2)
  // from the corner. Plus what rounding may move a point by.
  double reach(const std::array<Vec2, 3>& t) const {
    double sinHalf = 1.0, scale = 0.0;
    for (int s = 0; s < 3; ++s) {
      const Vec2 u = t[(s + 1) % 3] - t[s], v = t[(s + 2) % 3] - t[s];
      sinHalf = std::min(sinHalf, std::sin(0.5 * std::atan2(std::abs(cross2(u, v)), glm::dot(u, v))));
      scale = std::max({scale, glm::length(u), std::abs(t[s].x), std::abs(t[s].y)});
    }
    return noise_ / sinHalf + 1e-9 * scale;
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
