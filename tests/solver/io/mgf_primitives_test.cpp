// MGF's curved and solid primitives, written as MGF and imported: tessellated area against the
// analytic area (and the exact area of the inscribed polygons), planarity, and which side faces
// out.
#include "solver/io/mgf_primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "solver/scene/scene_error.h"
#include "tests/solver/io/mgf_test_scene.h"

namespace radmesh {
namespace {

using std::numbers::pi;
using test::importMgfText;

constexpr double kChordFactor = 0.99358685114420585;  // sin(pi/16) / (pi/16): 16-gon perimeter
constexpr double kDiscFactor = 0.97449535840443271;   // 8 sin(pi/8) / pi: 16-gon area

// A lit material and a centre vertex at (1, 2, 3) with axis +z (for ring and torus).
Scene primitive(const std::string& entity, const std::string& more = "") {
  const Scene s = importMgfText("m lamp =\n  ed 100\nv c =\n  p 1 2 3\n  n 0 0 1\n" + more + entity + "\n");
  EXPECT_NO_THROW(validateScene(s));
  return s;
}

Vec3 centroid(const Polygon& p) {
  Vec3 sum{0.0};
  for (const Vec3& v : p.vertices) sum += v;
  return sum / static_cast<double>(p.vertices.size());
}

// Every polygon's normal points away from (side > 0) or toward (side < 0) `inside(centroid)`.
template <class Inside>
void expectFacing(const Scene& s, double side, Inside inside) {
  for (const Polygon& p : s.polygons) {
    const Vec3 c = centroid(p);
    EXPECT_GT(side * glm::dot(newellNormal(p.vertices), c - inside(c)), 0.0) << p.origin;
  }
}

const Vec3 kCentre(1, 2, 3);

TEST(MgfPrimitives, SphereAreaIsTheInscribedBandsAndCloseToAnalytic) {
  const double r = 2.0;
  const Scene s = primitive("sph c 2");
  EXPECT_EQ(s.polygons.size(), size_t(kMgfSegmentsAround * kMgfSegmentsAcross));
  // Each band is 16 isosceles trapezoids between the circles at polar angles t0 and t1.
  double expected = 0.0;
  for (int b = 0; b < kMgfSegmentsAcross; ++b) {
    const double t0 = pi * b / kMgfSegmentsAcross, t1 = pi * (b + 1) / kMgfSegmentsAcross;
    const double half = std::sin(pi / kMgfSegmentsAround);
    const double chord0 = 2 * r * std::sin(t0) * half, chord1 = 2 * r * std::sin(t1) * half;
    const double apothemStep = r * (std::sin(t1) - std::sin(t0)) * std::cos(pi / kMgfSegmentsAround);
    const double height = std::hypot(apothemStep, r * (std::cos(t1) - std::cos(t0)));
    expected += kMgfSegmentsAround * 0.5 * (chord0 + chord1) * height;
  }
  EXPECT_NEAR(totalArea(s.polygons), expected, 1e-12 * expected);
  EXPECT_NEAR(totalArea(s.polygons) / (4 * pi * r * r), 0.968194, 1e-6);  // 3.2% short of the sphere
  expectFacing(s, +1.0, [](const Vec3&) { return kCentre; });
  expectFacing(primitive("sph c -2"), -1.0, [](const Vec3&) { return kCentre; });
}

TEST(MgfPrimitives, CylinderAreaIsTheInscribedPrism) {
  const Scene s = primitive("cyl c 0.5 e", "v e =\n  p 1 2 7\n");
  EXPECT_EQ(s.polygons.size(), size_t(kMgfSegmentsAround));
  EXPECT_NEAR(totalArea(s.polygons), 2 * pi * 0.5 * 4.0 * kChordFactor, 1e-12);
  const auto axis = [](const Vec3& p) { return Vec3(1, 2, p.z); };
  expectFacing(s, +1.0, axis);
  expectFacing(primitive("cyl c -0.5 e", "v e =\n  p 1 2 7\n"), -1.0, axis);
}

TEST(MgfPrimitives, ConeAreaIsTheInscribedFrustumAndItsApexIsATriangle) {
  // Radii 1 and 3 over height 2, along a slanted axis: slant height sqrt(2^2 + 2^2).
  const Scene s = primitive("cone c 1 e 3", "v e =\n  p 1 2 5\n");
  const double slantChord = std::hypot(2.0 * std::cos(pi / 16), 2.0);  // along a trapezoid's middle
  EXPECT_NEAR(totalArea(s.polygons), 16 * 0.5 * (2 * std::sin(pi / 16)) * (1.0 + 3.0) * slantChord, 1e-12);
  EXPECT_NEAR(totalArea(s.polygons) / (pi * (1.0 + 3.0) * std::hypot(2.0, 2.0)), 0.984087, 1e-6);  // 1.6% short
  expectFacing(s, +1.0, [](const Vec3& p) { return Vec3(1, 2, p.z); });
  const Scene apex = primitive("cone c 1 e 0", "v e =\n  p 1 2 5\n");
  for (const Polygon& p : apex.polygons) EXPECT_EQ(p.vertices.size(), 3u);
}

TEST(MgfPrimitives, RingAndDiscAreTheInscribedPolygonsFacingTheNormal) {
  const Scene disc = primitive("ring c 0 2");
  ASSERT_EQ(disc.polygons.size(), 1u);
  EXPECT_EQ(disc.polygons[0].vertices.size(), size_t(kMgfSegmentsAround));
  EXPECT_NEAR(totalArea(disc.polygons), pi * 4.0 * kDiscFactor, 1e-12);
  EXPECT_GT(newellNormal(disc.polygons[0].vertices).z, 0.0);
  const Scene ring = primitive("ring c 1 2");
  EXPECT_EQ(ring.polygons.size(), size_t(kMgfSegmentsAround));
  EXPECT_NEAR(totalArea(ring.polygons), pi * (4.0 - 1.0) * kDiscFactor, 1e-12);
  for (const Polygon& p : ring.polygons) EXPECT_GT(newellNormal(p.vertices).z, 0.0);
}

TEST(MgfPrimitives, TorusAreaIsCloseToAnalyticAndFacesOut) {
  // Inner radius 1.1, outer 1.4 (corridor.mgf's ring): tube 0.15 around a circle of 1.25.
  const Scene s = primitive("torus c 1.1 1.4");
  EXPECT_EQ(s.polygons.size(), size_t(kMgfSegmentsAround * kMgfSegmentsAcross));
  EXPECT_NEAR(totalArea(s.polygons) / (4 * pi * pi * 1.25 * 0.15), 0.958966, 1e-6);  // 4.1% short
  const auto spine = [](const Vec3& p) {
    const Vec3 radial(p.x - 1, p.y - 2, 0);
    return kCentre + 1.25 * glm::normalize(radial);
  };
  expectFacing(s, +1.0, spine);
  expectFacing(primitive("torus c -1.1 -1.4"), -1.0, spine);
}

TEST(MgfPrimitives, PrismIsAClosedSolidFacingOut) {
  // The specification's unit cube: base looking down -z, extruded up by 1.
  const Scene s = primitive("prism q0 q1 q2 q3 1",
                            "v q0 =\n p 0 0 0\nv q1 =\n p 0 1 0\nv q2 =\n p 1 1 0\nv q3 =\n p 1 0 0\n");
  EXPECT_EQ(s.polygons.size(), 6u);
  EXPECT_NEAR(totalArea(s.polygons), 6.0, 1e-12);
  expectFacing(s, +1.0, [](const Vec3&) { return Vec3(0.5, 0.5, 0.5); });
  Vec3 closed{0.0};  // the normals of a closed surface, weighted by area, cancel
  for (const Polygon& p : s.polygons) closed += newellNormal(p.vertices);
  EXPECT_NEAR(glm::length(closed), 0.0, 1e-12);
  const Scene inward = primitive("prism q0 q1 q2 q3 -1",
                                 "v q0 =\n p 0 0 0\nv q1 =\n p 0 1 0\nv q2 =\n p 1 1 0\nv q3 =\n p 1 0 0\n");
  expectFacing(inward, -1.0, [](const Vec3&) { return Vec3(0.5, 0.5, -0.5); });
}

TEST(MgfPrimitives, MirroredPrimitivesStillFaceOut) {
  const Scene s = primitive("xf -mx -t 4 0 0\ncyl c 0.5 e\nxf", "v e =\n  p 1 2 7\n");
  expectFacing(s, +1.0, [](const Vec3& p) { return Vec3(3, 2, p.z); });
}

TEST(MgfPrimitives, BadRadiiAreRefusedWithAFix) {
  for (const char* bad : {"cone c 1 e -1", "cone c 0 e 0", "ring c 2 1", "torus c 1 -2", "sph c 0",
                          "cyl c 1 c"}) {
    try {
      primitive(bad, "v e =\n  p 1 2 5\n");
      ADD_FAILURE() << bad << " was accepted";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("line 8: "), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("(fix: "), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace radmesh
