#include "solver/geometry/polygon_clip.h"

#include <algorithm>
#include <cmath>

namespace radmesh {

namespace {

int sideOf(const Vec2& p, int axis, double value, double noiseM) {
  const double d = p[axis] - value;
  return d > noiseM ? 1 : (d < -noiseM ? -1 : 0);
}

// Where segment pq meets the line, computed from the endpoint lower along the axis whichever way
// the edge runs, and placed exactly on the line.
Vec2 crossing(Vec2 p, Vec2 q, int axis, double value) {
  if (q[axis] < p[axis]) std::swap(p, q);
  const double t = (value - p[axis]) / (q[axis] - p[axis]);
  Vec2 r = p + t * (q - p);
  r[axis] = value;
  return r;
}

// A polygon ending this close to a grid line (a fraction of the cell) is not cut there: a model
// moved by a nanometre off the grid would gain a strip of patches a nanometre wide along it.
constexpr double kGridSnap = 1e-6;

// Splits at every grid line along `axis` strictly inside the polygon, appending the pieces.
void sliceAlong(const std::vector<Vec2>& convex, int axis, double cellM, double noiseM,
                std::vector<std::vector<Vec2>>& out) {
  double lo = convex[0][axis], hi = lo;
  for (const Vec2& p : convex) {
    lo = std::min(lo, p[axis]);
    hi = std::max(hi, p[axis]);
  }
  const double snap = std::max(noiseM, kGridSnap * cellM);
  const double first = std::floor((lo + snap) / cellM) + 1.0;
  const double last = std::ceil((hi - snap) / cellM) - 1.0;
  std::vector<Vec2> rest = convex, below, above;
  for (double line = first; line <= last; line += 1.0) {
    splitConvex(rest, axis, line * cellM, noiseM, below, above);
    if (below.size() >= 3) out.push_back(below);
    rest.swap(above);
  }
  if (rest.size() >= 3) out.push_back(std::move(rest));
}

}  // namespace

void splitConvex(const std::vector<Vec2>& convex, int axis, double value, double noiseM,
                 std::vector<Vec2>& below, std::vector<Vec2>& above) {
  below.clear();
  above.clear();
  for (size_t i = 0; i < convex.size(); ++i) {
    const Vec2& p = convex[i];
    const Vec2& q = convex[(i + 1) % convex.size()];
    const int sp = sideOf(p, axis, value, noiseM), sq = sideOf(q, axis, value, noiseM);
    if (sp <= 0) below.push_back(p);
    if (sp >= 0) above.push_back(p);
    if (sp * sq < 0) {
      const Vec2 r = crossing(p, q, axis, value);
      below.push_back(r);
      above.push_back(r);
    }
  }
}

std::vector<std::vector<Vec2>> sliceByGrid(const std::vector<Vec2>& convex, double cellM, double noiseM) {
  std::vector<std::vector<Vec2>> columns, cells;
  sliceAlong(convex, 0, cellM, noiseM, columns);
  for (const auto& column : columns) sliceAlong(column, 1, cellM, noiseM, cells);
  return cells;
}

std::vector<std::vector<Vec2>> fanIntoQuads(const std::vector<Vec2>& convex) {
  std::vector<std::vector<Vec2>> out;
  const size_t k = convex.size();
  size_t i = 1;
  for (; i + 2 < k; i += 2) out.push_back({convex[0], convex[i], convex[i + 1], convex[i + 2]});
  if (i + 1 < k) out.push_back({convex[0], convex[i], convex[i + 1]});
  return out;
}

}  // namespace radmesh
