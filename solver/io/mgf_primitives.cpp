#include "solver/io/mgf_primitives.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "solver/io/mgf_error.h"

namespace radmesh {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Unit vectors u, v with u x v = axis (axis of unit length): the plane of a circle.
struct CircleFrame {
  Vec3 u, v, axis;
  Vec3 at(double angle) const { return std::cos(angle) * u + std::sin(angle) * v; }
};

CircleFrame frameAround(const Vec3& direction) {
  const Vec3 axis = glm::normalize(direction);
  // Cross with the coordinate axis least parallel to `axis`, so the result is well conditioned.
  const Vec3 a = glm::abs(axis);
  const Vec3 helper = a.x <= a.y && a.x <= a.z ? Vec3(1, 0, 0) : a.y <= a.z ? Vec3(0, 1, 0) : Vec3(0, 0, 1);
  const Vec3 u = glm::normalize(glm::cross(helper, axis));
  return {u, glm::cross(axis, u), axis};
}

// Modulo so that the last segment ends exactly where the first begins.
double angleAround(int k) { return kTwoPi * (k % kMgfSegmentsAround) / kMgfSegmentsAround; }

void turnInside(MgfPolygons& polygons) {
  for (auto& p : polygons) std::reverse(p.begin(), p.end());
}

// +1 for outward normals, -1 for inward; MGF gives the side by the sign of both radii, which must
// agree (one may be zero). `what` names the entity for the message.
double sideOfRadii(double r1, double r2, const char* what) {
  if ((r1 < 0.0 && r2 > 0.0) || (r1 > 0.0 && r2 < 0.0) || (r1 == 0.0 && r2 == 0.0))
    throw MgfError(std::string(what) + " radii must be both >= 0 or both <= 0, and not both zero",
                   "give positive radii for an outward surface, negative for an inward one");
  return r1 + r2 > 0.0 ? 1.0 : -1.0;
}

Vec3 requireNormal(const Vec3& normal, const char* what) {
  if (!(glm::length(normal) > 0.0))
    throw MgfError(std::string(what) + " centre vertex has no normal",
                   "give the centre vertex a normal (n dx dy dz) along the axis");
  return normal;
}

}  // namespace

MgfPolygons tessellateSphere(const Vec3& centre, double radius) {
  if (radius == 0.0) throw MgfError("sphere radius is zero", "give a non-zero radius");
  const double r = std::abs(radius);
  const auto point = [&](int band, int k) {
    const double polar = std::numbers::pi * band / kMgfSegmentsAcross;
    const double around = angleAround(k);
    return centre + r * Vec3(std::sin(polar) * std::cos(around), std::sin(polar) * std::sin(around),
                             std::cos(polar));
  };
  MgfPolygons out;
  for (int b = 0; b < kMgfSegmentsAcross; ++b)
    for (int k = 0; k < kMgfSegmentsAround; ++k)
      out.push_back({point(b, k), point(b + 1, k), point(b + 1, k + 1), point(b, k + 1)});
  if (radius < 0.0) turnInside(out);
  return out;
}

MgfPolygons tessellateCone(const Vec3& end1, double radius1, const Vec3& end2, double radius2) {
  const double side = sideOfRadii(radius1, radius2, "cone/cylinder");
  if (!(glm::length(end2 - end1) > 0.0))
    throw MgfError("the two end vertices coincide", "give the axis a non-zero length");
  const CircleFrame f = frameAround(end2 - end1);
  const double r1 = std::abs(radius1);
  const double r2 = std::abs(radius2);
  MgfPolygons out;
  for (int k = 0; k < kMgfSegmentsAround; ++k) {
    const Vec3 a = f.at(angleAround(k));
    const Vec3 b = f.at(angleAround(k + 1));
    out.push_back({end1 + r1 * a, end1 + r1 * b, end2 + r2 * b, end2 + r2 * a});
  }
  if (side < 0.0) turnInside(out);
  return out;
}

MgfPolygons tessellateRing(const Vec3& centre, const Vec3& normal, double rMin, double rMax) {
  if (rMin < 0.0 || !(rMax > rMin))
    throw MgfError("ring radii need 0 <= rmin < rmax",
                   "give the inner radius first, then a larger outer one");
  const CircleFrame f = frameAround(requireNormal(normal, "ring"));
  MgfPolygons out;
  if (rMin == 0.0) {
    std::vector<Vec3> disc;
    for (int k = 0; k < kMgfSegmentsAround; ++k) disc.push_back(centre + rMax * f.at(angleAround(k)));
    out.push_back(disc);
    return out;
  }
  for (int k = 0; k < kMgfSegmentsAround; ++k) {
    const Vec3 a = f.at(angleAround(k));
    const Vec3 b = f.at(angleAround(k + 1));
    out.push_back({centre + rMax * a, centre + rMax * b, centre + rMin * b, centre + rMin * a});
  }
  return out;
}

MgfPolygons tessellateTorus(const Vec3& centre, const Vec3& normal, double rMin, double rMax) {
  const double side = sideOfRadii(rMin, rMax, "torus");
  if (!(std::abs(rMax) > std::abs(rMin)))
    throw MgfError("torus outer radius must be larger than the inner one",
                   "give the inner radius first, then a larger outer one");
  const CircleFrame f = frameAround(requireNormal(normal, "torus"));
  const double spine = 0.5 * (std::abs(rMax) + std::abs(rMin));  // centre line of the tube
  const double tube = 0.5 * (std::abs(rMax) - std::abs(rMin));
  const auto point = [&](int k, int j) {
    const double across = kTwoPi * (j % kMgfSegmentsAcross) / kMgfSegmentsAcross;
    return centre + (spine + tube * std::cos(across)) * f.at(angleAround(k)) +
           tube * std::sin(across) * f.axis;
  };
  MgfPolygons out;
  for (int k = 0; k < kMgfSegmentsAround; ++k)
    for (int j = 0; j < kMgfSegmentsAcross; ++j)
      out.push_back({point(k, j), point(k + 1, j), point(k + 1, j + 1), point(k, j + 1)});
  if (side < 0.0) turnInside(out);
  return out;
}

MgfPolygons tessellatePrism(const std::vector<Vec3>& base, double length) {
  if (length == 0.0) throw MgfError("prism length is zero", "give a non-zero length");
  const Vec3 n = newellNormal(base);
  if (!(glm::length(n) > 0.0))
    throw MgfError("the prism's base polygon has zero area", "give base vertices that span an area");
  // MGF extrudes against the base's normal, so that with a positive length all faces point out.
  const Vec3 shift = -length * glm::normalize(n);
  MgfPolygons out{base};
  std::vector<Vec3> top;
  for (auto it = base.rbegin(); it != base.rend(); ++it) top.push_back(*it + shift);
  out.push_back(top);
  for (size_t i = 0; i < base.size(); ++i) {
    const Vec3& a = base[i];
    const Vec3& b = base[(i + 1) % base.size()];
    out.push_back({a, a + shift, b + shift, b});
  }
  return out;
}

}  // namespace radmesh
