// Each file under tests/data/repaired/mgf_* is one that real tools write and MGF's reference parser
// opens: radmesh opens it too, repairs it as that parser does, and reports each kind of repair
// once, with where it first applied and how often.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "solver/io/mgf_color.h"
#include "solver/io/mgf_import.h"
#include "solver/io/scene_loader.h"
#include "tests/solver/io/mgf_test_scene.h"
#include "tests/test_paths.h"

namespace radmesh {
namespace {

struct Repaired {
  Scene scene;
  std::vector<std::string> warnings;
};

Repaired repaired(const std::string& name) {
  Repaired r;
  r.scene = loadScene(test::dataPath("repaired/" + name).string(), &r.warnings);  // also validates
  return r;
}

// The one warning that contains `text`; fails unless exactly one does.
std::string warningWith(const Repaired& r, const std::string& text) {
  const auto n = std::count_if(r.warnings.begin(), r.warnings.end(),
                               [&](const std::string& w) { return w.find(text) != std::string::npos; });
  EXPECT_EQ(n, 1) << "warnings naming '" << text << "'";
  for (const std::string& w : r.warnings)
    if (w.find(text) != std::string::npos) return w;
  return {};
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(MgfRepair, UnknownEntitiesAreCountedAndSkipped) {
  const Repaired r = repaired("mgf_unknown_entity.mgf");
  ASSERT_EQ(r.scene.polygons.size(), 1u);
  EXPECT_DOUBLE_EQ(totalArea(r.scene.polygons), 1.0);
  ASSERT_EQ(r.warnings.size(), 2u);
  const std::string sphere = warningWith(r, "unknown entity 'sphere' skipped");
  EXPECT_TRUE(contains(sphere, "mgf_unknown_entity.mgf: line 13:")) << sphere;
  EXPECT_TRUE(contains(sphere, "(2 times)")) << sphere;
  const std::string glow = warningWith(r, "unknown entity 'glow' skipped");
  EXPECT_TRUE(contains(glow, "line 14:")) << glow;
  EXPECT_FALSE(contains(glow, "times)")) << glow;
}

// rd 1 is legal MGF (above 1 is refused: MgfBadInput.*), and white walls write it with MGF's white
// to three digits, cxy 0.333 0.333: lowered to 0.99 with the one warning, and no gamut warning.
TEST(MgfRepair, ReflectanceOfOneIsLoweredTo099) {
  const Repaired r = repaired("mgf_rd_one.mgf");
  ASSERT_EQ(r.scene.materials.size(), 3u);
  for (int m : {1, 2}) EXPECT_NEAR(luminance(r.scene.materials[m].rho), kHighestReflectance, 1e-12) << m;
  for (int m : {1, 2})
    for (int c = 0; c < 3; ++c) EXPECT_LT(r.scene.materials[m].rho[c], 1.0) << m;
  ASSERT_EQ(r.warnings.size(), 1u) << r.warnings.back();
  EXPECT_EQ(r.warnings[0],
            test::dataPath("repaired/mgf_rd_one.mgf").string() +
                ": line 9: rd 1 lowered to 0.99 (a reflectance of 1 never lets light die out) (2 times)");
}

TEST(MgfRepair, AFaceAFifthOffItsPlaneIsTriangulated) {
  const Repaired r = repaired("mgf_bent_quad.mgf");
  ASSERT_EQ(r.scene.polygons.size(), 2u);
  const double h = std::sqrt(0.5);
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{1, 1, h}, d{0, 1, 0};
  // Split along one diagonal or the other; either way the triangles use the face's own corners.
  const double alongAc = polygonArea({a, b, c}) + polygonArea({a, c, d});
  const double alongBd = polygonArea({a, b, d}) + polygonArea({b, c, d});
  const double area = totalArea(r.scene.polygons);
  EXPECT_TRUE(std::abs(area - alongAc) < 1e-12 || std::abs(area - alongBd) < 1e-12) << area;
  for (const Polygon& p : r.scene.polygons) EXPECT_EQ(p.vertices.size(), 3u);
  EXPECT_TRUE(contains(warningWith(r, "f split into triangles"), "line 13:"));
}

TEST(MgfRepair, FacesThatCannotBeBuiltAreSkippedByName) {
  const Repaired r = repaired("mgf_undefined_vertex.mgf");
  ASSERT_EQ(r.scene.polygons.size(), 1u);
  EXPECT_DOUBLE_EQ(totalArea(r.scene.polygons), 0.5);
  ASSERT_EQ(r.warnings.size(), 3u);
  EXPECT_TRUE(contains(warningWith(r, "f skipped: v 'c' is not defined"), "line 14:"));
  EXPECT_TRUE(contains(warningWith(r, "f skipped: the face has fewer than 3 distinct vertices"), "line 15:"));
  // On a line: glTF's reader drops such a triangle, and the whole file was refused here.
  EXPECT_TRUE(contains(warningWith(r, "f skipped: it has no area (its vertices are collinear, or its outline crosses itself into parts that cancel)"), "line 16:"));
}

// A flat face whose outline crosses itself was refused with the whole scene (by the mesher); it is
// skipped by name, as one that is bent and crosses itself was.
TEST(MgfRepair, FlatFacesThatCrossThemselvesAreSkippedByName) {
  const Repaired r = repaired("mgf_crossing_faces.mgf");
  ASSERT_EQ(r.scene.polygons.size(), 1u);
  EXPECT_NEAR(totalArea(r.scene.polygons), 1.6 * 1.6, 1e-12);
  ASSERT_EQ(r.warnings.size(), 2u);
  EXPECT_TRUE(contains(warningWith(r, "f skipped: its outline crosses itself (its convex parts cover"), "line 15:"));
  EXPECT_TRUE(contains(warningWith(r, "f skipped: it has no area (its vertices are collinear, or its outline "
                                      "crosses itself into parts that cancel)"),
                       "line 16:"));
}

// A face that lists a triangle's corners 30 000 times over is skipped with the same words as one
// that goes round twice, and after as little work (it was ear-clipped vertex by vertex: 50 s).
TEST(MgfRepair, AFaceGoingRoundATriangle30000TimesIsSkippedByName) {
  std::string rounds;
  for (int k = 0; k < 30000; ++k) rounds += " a b c";
  std::vector<std::string> warnings;
  const Scene scene = test::importMgfText(test::kUnitSquare + "m light\nf a b c d\nf" + rounds + "\n", &warnings);
  EXPECT_EQ(scene.polygons.size(), 1u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_TRUE(contains(warnings[0], "line 13: f skipped: its outline crosses itself (its outline goes round part of "
                                    "it 30000 times) (fix: split it into faces that do not cross themselves)"))
      << warnings[0];
}

// y = 0 is the one chromaticity outside the diagram that MGF's reference parser opens (the others
// are refused: MgfValuesCli.*).
TEST(MgfRepair, AChromaticityOfYZeroIsRaisedIntoTheDiagram) {
  const Repaired r = repaired("mgf_color_outside_gamut.mgf");
  ASSERT_EQ(r.scene.materials.size(), 2u);
  EXPECT_NEAR(luminance(r.scene.materials[1].rho), 0.5, 1e-9);
  ASSERT_EQ(r.warnings.size(), 2u);
  const std::string raised =
      warningWith(r, "line 7: cxy y 0 (light of no luminance, which rd and ed cannot scale) raised to 1e-06");
  EXPECT_TRUE(contains(raised, "(2 times)")) << raised;
  EXPECT_TRUE(contains(warningWith(r, "outside the Rec. 709 gamut"), "material 'odd'"));
}

}  // namespace
}  // namespace radmesh
