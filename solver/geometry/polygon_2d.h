#pragma once
// Plane geometry shared by the polygon helpers: points in a polygon's own 2D frame, and the signed
// distances and areas their tolerances are stated in.
#include <glm/glm.hpp>
#include <vector>

namespace radmesh {

using Vec2 = glm::dvec2;

inline double cross2(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }

// Signed distance of p from the line through a and b: positive on the left (counter-clockwise
// side). Zero when a and b coincide, so degenerate edges never look convex.
inline double sideOfLine(const Vec2& a, const Vec2& b, const Vec2& p) {
  const double length = glm::length(b - a);
  return length > 0.0 ? cross2(b - a, p - a) / length : 0.0;
}

// Shoelace area, positive for a counter-clockwise polygon. Relative to the first vertex so that
// large coordinates do not swamp small polygons.
inline double signedArea(const std::vector<Vec2>& polygon) {
  double twice = 0.0;
  for (size_t i = 1; i + 1 < polygon.size(); ++i)
    twice += cross2(polygon[i] - polygon[0], polygon[i + 1] - polygon[0]);
  return 0.5 * twice;
}

// How many times the polygon winds around p, counter-clockwise positive (p off its edges).
inline int windingNumber(const std::vector<Vec2>& polygon, const Vec2& p) {
  int winding = 0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[(i + 1) % polygon.size()];
    if (a.y <= p.y && b.y > p.y && cross2(b - a, p - a) > 0.0) ++winding;       // upward, p on its left
    else if (a.y > p.y && b.y <= p.y && cross2(b - a, p - a) < 0.0) --winding;  // downward, p on its right
  }
  return winding;
}

// Length scale of a polygon (its bounding-box diagonal) from which tolerances are derived.
inline double extentOf(const std::vector<Vec2>& polygon) {
  if (polygon.empty()) return 0.0;
  Vec2 lo = polygon[0], hi = polygon[0];
  for (const Vec2& p : polygon) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return glm::length(hi - lo);
}

}  // namespace radmesh
