#include "solver/projection/projection.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include <glm/gtc/type_ptr.hpp>

namespace radmesh {

glm::dvec2 ProjectionFace::pixelCentre(int column, int row) const {
  return {a0 + (column + 0.5) * pixelWidth(), b0 + (row + 0.5) * pixelHeight()};
}

Vec3 ProjectionFace::toLocal(glm::dvec2 faceAB) const {
  const Vec3 onFace{faceAB.x, faceAB.y, 1.0};
  Vec3 local{0.0};
  for (int k = 0; k < 3; ++k) local[axis[k]] = sign[k] * onFace[k];
  return local;
}

Vec3 toShooterFrame(const Patch& shooter, const Vec3& point) {
  // Differences first: a scene far from the origin keeps its precision near the shooter.
  const Vec3 d = point - shooter.centroid;
  return {glm::dot(d, shooter.frame.u), glm::dot(d, shooter.frame.v), glm::dot(d, shooter.frame.n)};
}

Vec3 directionInShooterFrame(const Patch& shooter, const Vec3& direction) {
  const Frame& f = shooter.frame;
  return {glm::dot(direction, f.u), glm::dot(direction, f.v), glm::dot(direction, f.n)};
}

LocalPolygon toShooterFrame(const Patch& shooter, const Patch& patch) {
  LocalPolygon local;
  local.vertexCount = patch.vertexCount;
  for (int k = 0; k < 4; ++k)
    local.vertices[k] = k < patch.vertexCount ? toShooterFrame(shooter, patch.vertices[k]) : Vec3(0.0);
  local.normal = directionInShooterFrame(shooter, patch.normal);
  local.centroid = toShooterFrame(shooter, patch.centroid);
  local.planeOffset = glm::dot(local.normal, local.centroid);
  return local;
}

std::optional<LocalPolygon> inShooterView(const Patch& shooter, const Patch& patch) {
  const LocalPolygon local = toShooterFrame(shooter, patch);
  double highest = local.vertices[0].z;
  for (int k = 1; k < local.vertexCount; ++k) highest = std::max(highest, local.vertices[k].z);
  if (highest <= 0.0) return std::nullopt;
  return local;
}

Vec3 toFace(const ProjectionFace& face, const Vec3& local) {
  // Indexed loads: glm's operator[] is a switch, a branch per coordinate in the projection's inner loop.
  const double* xyz = glm::value_ptr(local);
  return {face.sign[0] * xyz[face.axis[0]], face.sign[1] * xyz[face.axis[1]], face.sign[2] * xyz[face.axis[2]]};
}

double inverseDepthAlong(const LocalPolygon& patch, const ProjectionFace& face, glm::dvec2 faceAB) {
  const Vec3 m = toFace(face, patch.normal);
  return (m.x * faceAB.x + m.y * faceAB.y + m.z) / patch.planeOffset;
}

namespace {

// The point where edge (p, q) crosses depth = nearDepth, computed from the pair in a fixed order
// so that two patches sharing the edge get the very same point (and so share the clipped edge).
Vec3 nearCrossing(const Vec3& p, const Vec3& q, double nearDepth) {
  const bool pFirst = std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z);
  const Vec3& s = pFirst ? p : q;
  const Vec3& t = pFirst ? q : p;
  const double f = (nearDepth - s.z) / (t.z - s.z);
  Vec3 crossing = s + f * (t - s);
  crossing.z = nearDepth;
  return crossing;
}

// A parallel projection: nothing to clip (the frame starts behind the scene), (a, b) map linearly,
// and -depth = (m.x a + m.y b - planeOffset) / m.z on the patch's plane.
bool projectParallel(const LocalPolygon& patch, const ProjectionFace& face, ScreenPolygon& out) {
  const Vec3 m = toFace(face, patch.normal);
  if (!(std::abs(m.z) > 1e-9)) return false;  // edge-on to the beam: no area
  const double scaleA = face.width / (face.a1 - face.a0);
  const double scaleB = face.height / (face.b1 - face.b0);
  out.vertexCount = patch.vertexCount;
  for (int k = 0; k < patch.vertexCount; ++k) {
    const Vec3 f = toFace(face, patch.vertices[k]);
    out.vertices[k] = {(f.x - face.a0) * scaleA, (f.y - face.b0) * scaleB};
  }
  out.inverseDepthX = m.x / (m.z * scaleA);
  out.inverseDepthY = m.y / (m.z * scaleB);
  out.inverseDepthC = (m.x * face.a0 + m.y * face.b0 - patch.planeOffset) / m.z;
  out.parallel = true;
  return true;
}

}  // namespace

bool projectOntoFace(const LocalPolygon& patch, const ProjectionFace& face, double nearDepth,
                     ScreenPolygon& out) {
  if (face.parallel) return projectParallel(patch, face, out);
  if (std::abs(patch.planeOffset) <= nearDepth) return false;  // edge-on: a line, no area

  // The window widened by two pixels: a polygon wholly beyond one of its edges (every vertex past
  // a plane through the eye, so the whole convex polygon is) would set up no pixel row or column
  // (setupPolygon widens its range by one), so it is refused before any division. Most patches in
  // view miss most of a hemicube's five faces. The planes are scaled by the pixel counts, which
  // leaves no division here either.
  const double columns = face.width, rows = face.height;
  const double marginA = 2.0 * (face.a1 - face.a0), marginB = 2.0 * (face.b1 - face.b0);
  const double a0 = face.a0 * columns - marginA, a1 = face.a1 * columns + marginA;
  const double b0 = face.b0 * rows - marginB, b1 = face.b1 * rows + marginB;
  std::array<Vec3, 4> faceVertices;
  bool anyInFront = false;
  int pastA0 = 0, pastA1 = 0, pastB0 = 0, pastB1 = 0;
  for (int k = 0; k < patch.vertexCount; ++k) {
    const Vec3 f = faceVertices[k] = toFace(face, patch.vertices[k]);
    anyInFront = anyInFront || f.z > nearDepth;
    pastA0 += f.x * columns < a0 * f.z;
    pastA1 += f.x * columns > a1 * f.z;
    pastB0 += f.y * rows < b0 * f.z;
    pastB1 += f.y * rows > b1 * f.z;
  }
  const int n = patch.vertexCount;
  if (!anyInFront || pastA0 == n || pastA1 == n || pastB0 == n || pastB1 == n) return false;

  // Sutherland-Hodgman against the near plane: a convex polygon stays convex, gains at most one vertex.
  std::array<Vec3, ScreenPolygon::kMaxVertices> clipped;
  int count = 0;
  for (int k = 0; k < patch.vertexCount; ++k) {
    const Vec3& p = faceVertices[k];
    const Vec3& q = faceVertices[(k + 1) % patch.vertexCount];
    const bool pIn = p.z > nearDepth;
    const bool qIn = q.z > nearDepth;
    if (pIn) clipped[count++] = p;
    if (pIn != qIn) clipped[count++] = nearCrossing(p, q, nearDepth);
  }

  const double scaleA = face.width / (face.a1 - face.a0);
  const double scaleB = face.height / (face.b1 - face.b0);
  out.vertexCount = count;
  for (int k = 0; k < count; ++k)
    out.vertices[k] = {(clipped[k].x / clipped[k].z - face.a0) * scaleA,
                       (clipped[k].y / clipped[k].z - face.b0) * scaleB};

  // 1/depth = (m . (a, b, 1)) / planeOffset, with a, b affine in pixel coordinates.
  const Vec3 m = toFace(face, patch.normal);
  const double h = patch.planeOffset;
  out.inverseDepthX = m.x / (scaleA * h);
  out.inverseDepthY = m.y / (scaleB * h);
  out.inverseDepthC = (m.x * face.a0 + m.y * face.b0 + m.z) / h;
  return true;
}

double sceneNearDepth(const std::vector<Patch>& patches) {
  Vec3 low(std::numeric_limits<double>::max());
  Vec3 high(-std::numeric_limits<double>::max());
  for (const Patch& p : patches)
    for (int k = 0; k < p.vertexCount; ++k) {
      low = glm::min(low, p.vertices[k]);
      high = glm::max(high, p.vertices[k]);
    }
  if (patches.empty()) return 0.0;
  const double magnitude = std::max(glm::length(low), glm::length(high));
  // Far below any feature, yet above the rounding of coordinates far from the origin.
  return std::max(1e-9 * glm::length(high - low), 64.0 * std::numeric_limits<double>::epsilon() * magnitude);
}

}  // namespace radmesh
