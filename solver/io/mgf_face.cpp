#include "solver/io/mgf_face.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "solver/io/mgf_error.h"
#include "solver/geometry/polygon_convex.h"
#include "solver/geometry/polygon_triangulate.h"

namespace radmesh {

namespace {

double sizeOf(const std::vector<Vec3>& vertices) {
  double extent = 0.0;
  for (const Vec3& v : vertices) extent = std::max(extent, glm::length(v - vertices.front()));
  return extent;
}

}  // namespace

void dropRepeatedVertices(std::vector<Vec3>& vertices) {
  if (vertices.empty()) return;
  const double tolerance = 1e-12 * sizeOf(vertices);
  std::vector<Vec3> kept;
  for (const Vec3& v : vertices)
    if (kept.empty() || glm::length(v - kept.back()) > tolerance) kept.push_back(v);
  while (kept.size() > 1 && glm::length(kept.back() - kept.front()) <= tolerance) kept.pop_back();
  vertices = std::move(kept);
}

std::vector<std::vector<Vec3>> planarFace(std::vector<Vec3> face, bool* split) {
  *split = false;
  dropRepeatedVertices(face);
  if (face.size() < 3)
    throw MgfError("the face has fewer than 3 distinct vertices",
                   "remove the face or give it at least 3 vertices at different places");
  if (hasZeroArea(face))  // glTF's reader drops such triangles too
    throw MgfError("it has no area (its vertices are collinear, or its outline crosses itself into parts that cancel)",
                   "remove the face, or move its vertices so that it encloses an area once");
  const Vec3 normal = newellNormal(face);
  const double size = sizeOf(face);
  const Vec3 n = glm::normalize(normal);
  double offPlane = 0.0;
  for (const Vec3& v : face) offPlane = std::max(offPlane, std::abs(glm::dot(v - face.front(), n)));
  const bool flat = offPlane <= kMgfFlatnessTolerance * size;
  // Counter-clockwise 2D coordinates seen from the front, so ear clipping keeps the orientation.
  // u along the in-plane part of the chord to the farthest vertex: well away from zero length.
  Vec3 far = face[0];
  for (const Vec3& p : face)
    if (glm::length(p - face[0]) > glm::length(far - face[0])) far = p;
  const Vec3 chord = far - face[0] - glm::dot(far - face[0], n) * n;
  if (!(glm::length(chord) > kMgfFlatnessTolerance * size))
    throw MgfError("the face is folded over itself", "split it into flat faces");
  const Vec3 u = glm::normalize(chord);
  const Vec3 v = glm::cross(n, u);
  std::vector<Vec2> flat2d;
  for (const Vec3& p : face) flat2d.push_back({glm::dot(p - face[0], u), glm::dot(p - face[0], v)});
  if (flat) {
    // As the mesher would find it, but here the face alone is skipped, as MGF's readers pass over
    // what they cannot draw, rather than the whole scene refused.
    std::string crossing;
    convexCover(flat2d, 1e-12 * size, crossing);
    if (!crossing.empty())
      throw MgfError("its outline crosses itself (" + crossing + ")", "split it into faces that do not cross themselves");
    return {face};
  }
  std::vector<std::vector<Vec3>> triangles;
  double area = 0.0;
  for (const auto& t : triangulatePolygon(flat2d, 1e-12 * size)) {
    triangles.push_back({face[t[0]], face[t[1]], face[t[2]]});
    area += cross2(flat2d[t[1]] - flat2d[t[0]], flat2d[t[2]] - flat2d[t[0]]) / 2.0;
  }
  // Ear clipping covers a simple polygon exactly; a shortfall means the outline crosses itself.
  if (std::abs(area - signedArea(flat2d)) > 1e-9 * size * size)
    throw MgfError("the face is not flat and its outline crosses itself",
                   "split it into flat faces that do not cross themselves");
  *split = true;
  return triangles;
}

}  // namespace radmesh
