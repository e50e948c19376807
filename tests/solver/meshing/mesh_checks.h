#pragma once
// Properties every patch of meshScene must have (the paper's section 1.6 and issue 2), shared by
// the meshing and built-in scene tests.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "solver/meshing/grid_turn.h"
#include "solver/meshing/patch.h"
#include "solver/scene/scene.h"

namespace radmesh::test {

inline int dominantAxis(const Vec3& n) {
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(n[k]) > std::abs(n[axis])) axis = k;
  return axis;
}

// Convex, planar, counter-clockwise around its unit normal, with the area and centroid of its
// vertices, an orthonormal right-handed frame whose n is the normal, and a bounding box inside one
// grid cell along the two axes spanning its dominant plane. Returns false (after reporting) on
// the first failure so that a broken mesh does not print thousands of lines.
inline bool patchIsValid(const Patch& p, double cellM, const std::string& where, const GridTurn& turn = {}) {
  SCOPED_TRACE(where);
  const double tol = 1e-9;
  if (p.vertexCount != 3 && p.vertexCount != 4) {
    ADD_FAILURE() << "vertexCount " << p.vertexCount;
    return false;
  }
  bool ok = true;
  const auto check = [&](bool condition, const std::string& what) {
    if (!condition) ADD_FAILURE() << what;
    ok = ok && condition;
  };
  std::vector<Vec3> v(p.vertices.begin(), p.vertices.begin() + p.vertexCount);
  double size = 0.0;
  for (const Vec3& a : v) size = std::max(size, glm::length(a - v[0]));
  check(std::abs(glm::length(p.normal) - 1.0) < 1e-12, "normal is not unit");
  for (int i = 0; i < p.vertexCount; ++i) {
    const Vec3 &a = v[i], &b = v[(i + 1) % v.size()], &c = v[(i + 2) % v.size()];
    // Strictly left turns around the normal: convex and counter-clockwise.
    check(glm::dot(glm::cross(b - a, c - b), p.normal) > 0.0,
          "turns right or goes straight at vertex " + std::to_string((i + 1) % v.size()));
    check(std::abs(glm::dot(a - p.centroid, p.normal)) <= tol * size + 1e-9, "vertex off the patch plane");
  }
  // Vertices far from the origin are rounded to their own magnitude's precision.
  double magnitude = 0.0, perimeter = 0.0;
  for (size_t i = 0; i < v.size(); ++i) {
    magnitude = std::max({magnitude, std::abs(v[i].x), std::abs(v[i].y), std::abs(v[i].z)});
    perimeter += glm::length(v[(i + 1) % v.size()] - v[i]);
  }
  const double rounding = 4.0 * DBL_EPSILON * magnitude * perimeter;
  check(std::abs(polygonArea(v) - p.areaM2) <= tol * p.areaM2 + rounding, "areaM2 is not the vertices' area");
  Vec3 centroid{0.0};
  double twice = 0.0;
  for (size_t i = 1; i + 1 < v.size(); ++i) {
    const double a = glm::length(glm::cross(v[i] - v[0], v[i + 1] - v[0]));
    centroid += a * (v[0] + v[i] + v[i + 1]) / 3.0;
    twice += a;
  }
  check(glm::length(centroid / twice - p.centroid) <= tol * size + 1e-9 + 8.0 * DBL_EPSILON * magnitude,
        "centroid is not the area centroid");
  const Frame& f = p.frame;
  check(glm::length(f.n - p.normal) < 1e-12, "frame n is not the normal");
  check(std::abs(glm::dot(f.u, f.v)) < 1e-12 && std::abs(glm::dot(f.u, f.n)) < 1e-12 &&
            std::abs(glm::dot(f.v, f.n)) < 1e-12,
        "frame is not orthogonal");
  check(std::abs(glm::length(f.u) - 1.0) < 1e-12 && std::abs(glm::length(f.v) - 1.0) < 1e-12,
        "frame is not unit");
  check(glm::dot(glm::cross(f.u, f.v), f.n) > 0.999999, "frame is not right-handed");
  // The grid cuts along the two axes spanning the dominant plane; a 45-degree face may take
  // either of its tied axes as dominant. The grid's axes, where it is turned.
  std::vector<Vec3> g = v;
  Vec3 normal = p.normal;
  if (turn.moved()) {
    for (Vec3& a : g) a = turn.toGrid(a);
    normal = turn.directionToGrid(p.normal);
  }
  const auto fitsOneCell = [&](int dropped) {
    for (int axis = 0; axis < 3; ++axis) {
      if (axis == dropped) continue;
      double lo = g[0][axis], hi = lo;
      for (const Vec3& a : g) {
        lo = std::min(lo, a[axis]);
        hi = std::max(hi, a[axis]);
      }
      // A turned grid's coordinates are small, but carry the world coordinates' rounding.
      const double slack = 1e-9 * cellM + 1e-14 * std::max(std::abs(lo), magnitude);
      if (std::floor((lo + slack) / cellM) != std::floor((hi - slack) / cellM)) return false;
    }
    return true;
  };
  const int n = dominantAxis(normal);
  bool fits = false;
  for (int axis = 0; axis < 3; ++axis)
    if (std::abs(normal[axis]) >= std::abs(normal[n]) - 1e-12) fits = fits || fitsOneCell(axis);
  check(fits, "spans more than one grid cell");
  return ok;
}

// Each patch on the grid its polygon is meshed on (gridsOf), or on the world grid.
inline void expectValidPatches(const std::vector<Patch>& patches, double cellM, const std::string& where,
                               const Grids* grids = nullptr) {
  static const GridTurn world;
  for (size_t i = 0; i < patches.size(); ++i)
    if (!patchIsValid(patches[i], cellM, where + ", patch " + std::to_string(i),
                      grids ? grids->of(static_cast<size_t>(patches[i].polygon)) : world))
      return;
}
inline void expectValidPatches(const std::vector<Patch>& patches, double cellM, const std::string& where,
                               const Scene& scene) {
  const Grids grids = gridsOf(scene);
  expectValidPatches(patches, cellM, where, &grids);
}

// Sum of patch areas per polygon equals the polygon's area to `relative`; each patch keeps the
// polygon's material and normal.
inline void expectAreaKept(const Scene& scene, const std::vector<Patch>& patches, double relative,
                           const std::string& where) {
  SCOPED_TRACE(where);
  std::vector<double> area(scene.polygons.size(), 0.0);
  for (const Patch& p : patches) {
    ASSERT_GE(p.polygon, 0);
    ASSERT_LT(p.polygon, static_cast<int>(scene.polygons.size()));
    const Polygon& polygon = scene.polygons[p.polygon];
    ASSERT_EQ(p.material, polygon.material);
    const Vec3 n = glm::normalize(newellNormal(polygon.vertices));
    ASSERT_NEAR(glm::dot(n, p.normal), 1.0, 1e-12) << "polygon " << p.polygon;
    area[p.polygon] += p.areaM2;
  }
  double total = 0.0, kept = 0.0;
  for (size_t i = 0; i < scene.polygons.size(); ++i) {
    const double expected = polygonArea(scene.polygons[i].vertices);
    EXPECT_NEAR(area[i], expected, relative * expected) << "polygon " << i << " " << scene.polygons[i].origin;
    total += expected;
    kept += area[i];
  }
  EXPECT_NEAR(kept, total, relative * total);
}

// Divergence theorem: sum of (centroid . normal) * area / 3 over a closed surface is its volume,
// positive when the faces point outward and negative when they point inward.
inline double signedVolume(const std::vector<Polygon>& polygons) {
  double volume = 0.0;
  for (const Polygon& p : polygons) {
    Vec3 mean{0.0};
    for (const Vec3& v : p.vertices) mean += v;
    mean /= static_cast<double>(p.vertices.size());
    // For a planar polygon any point of it gives the same dot with the normal.
    volume += glm::dot(mean, newellNormal(p.vertices)) / 6.0;
  }
  return volume;
}

}  // namespace radmesh::test
