#include "solver/meshing/grid_turn.h"

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace radmesh {

namespace {

// Edges within half a degree of a direction count as along it: exported walls are that straight.
const double kAlongRadians = 0.5 * std::numbers::pi / 180.0;

double wrapped(double angle) { return std::remainder(angle, 2.0 * std::numbers::pi); }

// An edge square to the axis: its length and its direction in the plane of the other two axes,
// times four, so that directions a quarter turn apart are one.
struct Edge {
  double length;
  double quadrupled;
};

struct AxisTurn {
  double radians = 0.0;
  double along = 0.0;    // edge length within kAlongRadians of the turn
  double aligned = 0.0;  // edge length along the world axes
  double total = 0.0;
};

AxisTurn turnAbout(const std::vector<Edge>& edges) {
  AxisTurn out;
  double c = 0.0, s = 0.0;
  for (const Edge& e : edges) {
    c += e.length * std::cos(e.quadrupled);
    s += e.length * std::sin(e.quadrupled);
    out.total += e.length;
  }
  if (!(out.total > 0.0)) return out;
  // The weighted mean direction, then the mean of the edges near it, which stray edges (a chair
  // at an angle) do not pull.
  const double mean = std::atan2(s, c);
  double offset = 0.0, near = 0.0;
  for (const Edge& e : edges) {
    const double d = wrapped(e.quadrupled - mean);
    if (std::abs(d) > 16.0 * kAlongRadians) continue;
    offset += e.length * d;
    near += e.length;
  }
  const double quadrupled = near > 0.0 ? wrapped(mean + offset / near) : mean;
  out.radians = quadrupled / 4.0;
  for (const Edge& e : edges) {
    if (std::abs(wrapped(e.quadrupled - quadrupled)) <= 4.0 * kAlongRadians) out.along += e.length;
    if (std::abs(wrapped(e.quadrupled)) <= 4.0 * kAlongRadians) out.aligned += e.length;
  }
  return out;
}

}  // namespace

double GridTurn::degrees() const { return radians * 180.0 / std::numbers::pi; }

Vec3 GridTurn::directionToGrid(const Vec3& world) const {
  const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
  const double c = std::cos(radians), s = std::sin(radians);
  Vec3 grid;
  grid[axis] = world[axis];
  grid[a1] = c * world[a1] + s * world[a2];
  grid[a2] = -s * world[a1] + c * world[a2];
  return grid;
}

Vec3 GridTurn::directionToWorld(const Vec3& grid) const {
  const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
  const double c = std::cos(radians), s = std::sin(radians);
  Vec3 world;
  world[axis] = grid[axis];
  world[a1] = c * grid[a1] - s * grid[a2];
  world[a2] = s * grid[a1] + c * grid[a2];
  return world;
}

Vec3 GridTurn::toGrid(const Vec3& world) const { return directionToGrid(world - pivot); }

Vec3 GridTurn::toWorld(const Vec3& grid) const { return directionToWorld(grid) + pivot; }

GridTurn gridTurnOf(const Scene& scene) {
  std::vector<const std::vector<Vec3>*> outlines;
  outlines.reserve(scene.polygons.size());
  for (const Polygon& polygon : scene.polygons) outlines.push_back(&polygon.vertices);
  return gridTurnOf(outlines);
}

GridTurn gridTurnOf(const std::vector<const std::vector<Vec3>*>& outlines) {
  std::array<std::vector<Edge>, 3> edges;
  double allEdges = 0.0;
  Vec3 low(INFINITY), high(-INFINITY);
  for (const std::vector<Vec3>* outline : outlines) {
    const std::vector<Vec3>& vertices = *outline;
    const size_t n = vertices.size();
    for (size_t i = 0; i < n; ++i) {
      const Vec3& p = vertices[i];
      low = glm::min(low, p);
      high = glm::max(high, p);
      const Vec3 d = vertices[(i + 1) % n] - p;
      const double length = glm::length(d);
      if (!(length > 0.0)) continue;
      allEdges += length;
      for (int a = 0; a < 3; ++a)
        if (std::abs(d[a]) <= std::sin(kAlongRadians) * length)
          edges[a].push_back({length, wrapped(4.0 * std::atan2(d[(a + 2) % 3], d[(a + 1) % 3]))});
    }
  }
  GridTurn best;
  double bestAlong = 0.0;
  for (int a = 0; a < 3; ++a) {
    const AxisTurn t = turnAbout(edges[a]);
    // A few edges that happen to lie square to an axis (a slanted roof's) do not turn the grid.
    const bool turned = t.along >= 0.5 * t.total && t.aligned < 0.5 * t.total && t.along >= 0.25 * allEdges;
    if (turned && t.along > bestAlong) {
      best.axis = a;
      best.radians = t.radians;
      bestAlong = t.along;
    }
  }
  // Along the axis the grid is the world's. Across it, grid lines pass through the corner of the
  // model's box in the grid's frame, as they pass through the world origin, where models are often
  // drawn from: a model turned about any point meshes as itself unturned with that corner at the
  // origin. The corner is found about the model's middle, so that site coordinates keep precision.
  if (best.turned()) {
    best.pivot = (low + high) / 2.0;
    best.pivot[best.axis] = 0.0;
    Vec3 corner(INFINITY);
    for (const std::vector<Vec3>* outline : outlines)
      for (const Vec3& v : *outline) corner = glm::min(corner, best.toGrid(v));
    corner[best.axis] = 0.0;
    best.pivot = best.toWorld(corner);
  }
  return best;
}

}  // namespace radmesh
