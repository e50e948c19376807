#include "solver/geometry/polygon_triangulate.h"

#include <algorithm>
#include <cmath>

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

class EarClipper {
 public:
  EarClipper(const std::vector<Vec2>& points, double noiseM)
      : p_(points), noise_(noiseM), ring_(static_cast<int>(points.size())) {}

  std::vector<std::array<int, 3>> run() {
    int i = 0;
    int stalled = 0;  // vertices visited since the last removal
    while (ring_.count() > 3) {
      if (degenerate(i) || (convex(i) && !blocked(i))) {
        // Revisit the neighbour next: removing a vertex can make it degenerate or an ear.
        const int neighbour = ring_.prev(i);
        if (!degenerate(i)) triangles_.push_back({neighbour, i, ring_.next(i)});
        ring_.remove(i);
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
  // (e.g. the far end of a seam) with an edge leaving it into the interior.
  bool blocked(int i) const {
    const int ia = ring_.prev(i), ic = ring_.next(i);
    const std::array<Vec2, 3> t{p_[ia], p_[i], p_[ic]};
    const Vec2 lo = glm::min(t[0], glm::min(t[1], t[2])) - noise_;
    const Vec2 hi = glm::max(t[0], glm::max(t[1], t[2])) + noise_;
    for (int j = ring_.next(ic); j != ia; j = ring_.next(j)) {
      const Vec2& q = p_[j];
      if (q.x < lo.x || q.y < lo.y || q.x > hi.x || q.y > hi.y) continue;
      std::array<double, 3> side;
      for (int s = 0; s < 3; ++s) side[s] = sideOfLine(t[s], t[(s + 1) % 3], q);
      if (*std::min_element(side.begin(), side.end()) < -noise_) continue;
      if (*std::min_element(side.begin(), side.end()) > noise_) return true;
      for (int other : {ring_.prev(j), ring_.next(j)})
        if (entersTriangle(t, side, q, p_[other])) return true;
    }
    return false;
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
        ring_.remove(i);
        return neighbour;
      }
    }
    return -1;
  }

  const std::vector<Vec2>& p_;
  double noise_;
  Ring ring_;
  std::vector<std::array<int, 3>> triangles_;
};

}  // namespace

std::vector<std::array<int, 3>> triangulatePolygon(const std::vector<Vec2>& ccw, double noiseM) {
  if (ccw.size() < 3) return {};
  return EarClipper(ccw, noiseM).run();
}

}  // namespace radmesh
