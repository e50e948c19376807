// The MGF importer on the shared reference scenes (counts, power and area against rpkCpp's
// figures in ../shared/scenes/SOURCES.md) and on small scenes whose result is known by hand.
#include "solver/io/mgf_import.h"

#include <gtest/gtest.h>

#include <cmath>

#include "solver/io/mgf_color.h"
#include "tests/solver/io/mgf_test_scene.h"
#include "tests/test_paths.h"

namespace radmesh {
namespace {

using test::importMgfText;
using test::kUnitSquare;

size_t emitterPolygons(const Scene& s) {
  size_t n = 0;
  for (const Polygon& p : s.polygons) n += s.materials[p.material].emits() ? 1 : 0;
  return n;
}

// rpkCpp reports power as area x ed / 183.07 lm/W (luminance only); radmesh divides by 179 lm/W
// and sums R + G + B of the emitter's colour at unit luminance (see docs/scene-formats.md).
double fromRpkPower(double rpkPowerW, double x, double y) {
  const Rgb unit = linearRgb(xyzFromChromaticity(x, y));
  return rpkPowerW * 183.07 / kWhiteEfficacyLmPerW * (unit.r + unit.g + unit.b);
}

struct SharedScene {
  const char* path;
  size_t polygons, emitters;
  double powerW, areaM2;                 // radmesh's figures
  double rpkAreaM2, rpkPowerW, lightX, lightY;  // SOURCES.md, and the emitters' cxy
  double areaVsRpk;                      // relative; tessellated primitives differ from rpkCpp's
};

void checkShared(const std::filesystem::path& path, const SharedScene& s) {
  std::vector<std::string> warnings;
  const Scene scene = importMgf(path.string(), &warnings);
  EXPECT_NO_THROW(validateScene(scene));
  EXPECT_EQ(scene.polygons.size(), s.polygons);
  EXPECT_EQ(emitterPolygons(scene), s.emitters);
  EXPECT_NEAR(emittedPowerW(scene), s.powerW, 1e-9 * s.powerW);
  EXPECT_NEAR(totalArea(scene.polygons), s.areaM2, 1e-9 * s.areaM2);
  EXPECT_NEAR(emittedPowerW(scene), fromRpkPower(s.rpkPowerW, s.lightX, s.lightY), 1e-5 * s.powerW);
  EXPECT_NEAR(totalArea(scene.polygons), s.rpkAreaM2, s.areaVsRpk * s.rpkAreaM2);
  EXPECT_FALSE(warnings.empty());  // every one of them uses rs or sides
}

TEST(MgfImport, CubeLoads) {
  RADMESH_REQUIRE_SHARED(path, "scenes/mgf/cube.mgf");
  checkShared(path, {"cube", 66, 2, 3323.023618, 728.2480063, 728.2478, 1092.478, 0.337, 0.337, 1e-6});
  // By hand: the light is one 1 x 1 square (two triangles) of ed 200000 at cxy .337 .337.
  const Rgb unit = linearRgb(xyzFromChromaticity(0.337, 0.337));
  EXPECT_NEAR(emittedPowerW(importMgf(path.string())), 200000.0 / 179.0 * (unit.r + unit.g + unit.b), 1e-6);
}

TEST(MgfImport, Office3Loads) {
  RADMESH_REQUIRE_SHARED(path, "scenes/mgf/office3/office.mgf");
  checkShared(path, {"office3", 12298, 130, 279.807997, 142.1206618, 142.1092, 91.1233, 0.333, 0.333, 1e-4});
}

TEST(MgfImport, Office2Loads) {
  RADMESH_REQUIRE_SHARED(path, "scenes/mgf/office2/office2.mgf");
  // 422 faces, 8 of them bent quads split in two.
  checkShared(path, {"office2", 430, 1, 42.99962158, 108.8220601, 108.8219, 14.2022, 0.3373, 0.3385, 1e-4});
}

TEST(MgfImport, CorridorLoads) {
  RADMESH_REQUIRE_SHARED(path, "scenes/mgf/corridor.mgf");
  checkShared(path, {"corridor", 355, 57, 37882.46925, 1361.055159, 1361.1998, 12454.256, 0.337, 0.337, 2e-4});
}

TEST(MgfImport, Examp1Loads) {
  RADMESH_REQUIRE_SHARED(path, "scenes/mgf/examp1.mgf");
  checkShared(path, {"examp1", 198, 32, 128.0072719, 1.060176004, 1.060177, 47.2047, 0.373, 0.385, 1e-5});
}

// --- Transforms, by hand ----------------------------------------------------------------------

void expectVertices(const Polygon& p, const std::vector<Vec3>& expected) {
  ASSERT_EQ(p.vertices.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i)
    EXPECT_NEAR(glm::length(p.vertices[i] - expected[i]), 0.0, 1e-12) << "vertex " << i;
}

TEST(MgfImport, TransformArgumentsActInTheOrderGiven) {
  // Rotate 90 degrees counter-clockwise about z, double, then move 1 along x.
  const Scene s = importMgfText(kUnitSquare + "xf -rz 90 -s 2 -t 1 0 0\nf a b c d\nxf\n");
  ASSERT_EQ(s.polygons.size(), 1u);
  expectVertices(s.polygons[0], {{1, 0, 0}, {1, 2, 0}, {-1, 2, 0}, {-1, 0, 0}});
}

TEST(MgfImport, RotationsAreCounterClockwiseAboutEachAxis) {
  const Scene s = importMgfText(kUnitSquare + "xf -rx 90\nf a b c d\nxf\nxf -ry 90\nf a b c d\nxf\n");
  ASSERT_EQ(s.polygons.size(), 2u);
  expectVertices(s.polygons[0], {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}});  // y -> z
  expectVertices(s.polygons[1], {{0, 0, 0}, {0, 0, -1}, {0, 1, -1}, {0, 1, 0}});  // x -> -z
}

TEST(MgfImport, NestedTransformsApplyTheInnerOneFirst) {
  const Scene s = importMgfText(kUnitSquare + "xf -t 10 0 0\nxf -s 3\nf a b c d\nxf\nf a b c d\nxf\n");
  ASSERT_EQ(s.polygons.size(), 2u);
  expectVertices(s.polygons[0], {{10, 0, 0}, {13, 0, 0}, {13, 3, 0}, {10, 3, 0}});
  expectVertices(s.polygons[1], {{10, 0, 0}, {11, 0, 0}, {11, 1, 0}, {10, 1, 0}});
}

TEST(MgfImport, ArraysPlaceEveryInstance) {
  // The specification's 3 x 5 grid: the first instance at (1, 1, 10), steps of 3 in x and y.
  const Scene s = importMgfText(kUnitSquare + "xf -t 1 1 10 -a 3 -t 3 0 0 -a 5 -t 0 3 0\nf a b c d\nxf\n");
  ASSERT_EQ(s.polygons.size(), 15u);
  for (size_t i = 0; i < 3; ++i)
    for (size_t j = 0; j < 5; ++j) {
      const Vec3 corner(1.0 + 3.0 * i, 1.0 + 3.0 * j, 10.0);
      expectVertices(s.polygons[i * 5 + j], {corner, corner + Vec3(1, 0, 0), corner + Vec3(1, 1, 0),
                                             corner + Vec3(0, 1, 0)});
    }
}

TEST(MgfImport, ArrayOfRotationsAndRepeatCount) {
  // -a 4 -rz 90: four copies around z; -i 2 -t 0 0 1 then lifts all of them by 2.
  const Scene s = importMgfText(kUnitSquare + "xf -a 4 -rz 90 -i 2 -t 0 0 1\nf a b c\nxf\n");
  ASSERT_EQ(s.polygons.size(), 4u);
  expectVertices(s.polygons[1], {{0, 0, 2}, {0, 1, 2}, {-1, 1, 2}});
  expectVertices(s.polygons[3], {{0, 0, 2}, {0, -1, 2}, {1, -1, 2}});
}

TEST(MgfImport, MirrorKeepsTheMirroredFaceFacingItsMirroredSide) {
  // Mirrored in z the up-facing square faces down: the vertex order is reversed to keep MGF's side.
  const Scene s = importMgfText(kUnitSquare + "v e =\n  p 0 0 1\nxf -mz\nf a b c d\nf a b e\nxf\n");
  ASSERT_EQ(s.polygons.size(), 2u);
  const Vec3 n = glm::normalize(newellNormal(s.polygons[0].vertices));
  EXPECT_NEAR(n.z, -1.0, 1e-12);
  // The wall facing -y before still faces -y: mirrors in z do not turn it.
  EXPECT_NEAR(glm::normalize(newellNormal(s.polygons[1].vertices)).y, -1.0, 1e-12);
  const std::vector<Vec3>& wall = s.polygons[1].vertices;
  EXPECT_NEAR(wall[0].z + wall[1].z + wall[2].z, -1.0, 1e-12);
}

TEST(MgfImport, VerticesTakeTheTransformWhereTheyAreUsed) {
  // Defined outside the xf, used inside it (as corridor.mgf's lights are).
  const Scene s = importMgfText(kUnitSquare + "xf -t 0 0 5\nf a b c\nxf\nf a b c\n");
  ASSERT_EQ(s.polygons.size(), 2u);
  EXPECT_DOUBLE_EQ(s.polygons[0].vertices[0].z, 5.0);
  EXPECT_DOUBLE_EQ(s.polygons[1].vertices[0].z, 0.0);
}

// --- Includes ---------------------------------------------------------------------------------

TEST(MgfImport, IncludesAreRelativeToTheIncludingFileAndTakeTheirTransform) {
  test::TempDir dir;
  test::writeMgf(dir, "parts/square.mgf", "i corner.mgf\nf a b c d\n");
  test::writeMgf(dir, "parts/corner.mgf", kUnitSquare);
  const std::string top = test::writeMgf(dir, "room.mgf", "i parts/square.mgf -t 0 0 2 -s 2\n");
  const Scene s = importMgf(top);
  ASSERT_EQ(s.polygons.size(), 1u);
  expectVertices(s.polygons[0], {{0, 0, 4}, {2, 0, 4}, {2, 2, 4}, {0, 2, 4}});
  EXPECT_EQ(s.polygons[0].origin, "square.mgf line 2: f");
}

// --- Faces ------------------------------------------------------------------------------------

TEST(MgfImport, FaceWithAHoleThroughASeamKeepsItsShapeAndOrientation) {
  // A 4 x 4 wall with a 2 x 2 window reached by a seam from v4 to v5, the window's outline
  // running clockwise against the wall's counter-clockwise one (as MGF's f entity requires).
  const Scene s = importMgfText(
      "m light =\n  ed 100\n"
      "v v1 =\n p 0 0 0\nv v2 =\n p 4 0 0\nv v3 =\n p 4 4 0\nv v4 =\n p 0 4 0\n"
      "v v5 =\n p 1 3 0\nv v6 =\n p 3 3 0\nv v7 =\n p 3 1 0\nv v8 =\n p 1 1 0\n"
      "f v1 v2 v3 v4 v5 v6 v7 v8 v5 v4\n");
  ASSERT_EQ(s.polygons.size(), 1u);
  EXPECT_EQ(s.polygons[0].vertices.size(), 10u);
  EXPECT_NEAR(polygonArea(s.polygons[0].vertices), 16.0 - 4.0, 1e-12);
  EXPECT_GT(newellNormal(s.polygons[0].vertices).z, 0.0);
  EXPECT_NO_THROW(validateScene(s));
}

TEST(MgfImport, RepeatedVerticesAreDropped) {
  const Scene s = importMgfText(kUnitSquare + "v b2 = b\nf a b b2 c c d a\n");
  ASSERT_EQ(s.polygons.size(), 1u);
  expectVertices(s.polygons[0], {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
}

TEST(MgfImport, BentFaceIsSplitIntoTrianglesWithItsOrientation) {
  std::vector<std::string> warnings;
  const Scene s = importMgfText(kUnitSquare + "v d2 = d\n  p 0 1 0.1\nf a b c d2\n", &warnings);
  ASSERT_EQ(s.polygons.size(), 2u);
  for (const Polygon& p : s.polygons) EXPECT_GT(newellNormal(p.vertices).z, 0.0);
  EXPECT_NO_THROW(validateScene(s));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("line 13: f split into triangles"), std::string::npos) << warnings[0];
}

// --- Materials and warnings -------------------------------------------------------------------

TEST(MgfImport, MaterialsTakeTheColourCurrentAtRdAndEd) {
  const Scene s = importMgfText(
      "c red =\n  cxy 0.64 0.33\n"
      "m lamp =\n  c red\n  rd 0.2\n  c\n  ed 179\n"  // red reflectance, neutral emission
      "v a =\n  p 0 0 0\nv b =\n  p 1 0 0\nv c =\n  p 0 1 0\nf a b c\n");
  ASSERT_EQ(s.materials.size(), 1u);
  const Material& m = s.materials[0];
  EXPECT_EQ(m.name, "lamp");
  EXPECT_NEAR(luminance(m.rho), 0.2, 1e-12);
  EXPECT_NEAR(m.rho.g, 0.0, 1e-12);
  EXPECT_NEAR(m.rho.b, 0.0, 1e-12);
  EXPECT_NEAR(m.emittance.r, 1.0, 1e-12);  // ed 179 lm/m^2 of white is 1 W/m^2 per channel
  EXPECT_NEAR(m.emittance.g, 1.0, 1e-12);
  EXPECT_NEAR(m.emittance.b, 1.0, 1e-12);
}

TEST(MgfImport, MaterialChangedAfterUseBecomesASecondMaterial) {
  const Scene s = importMgfText(kUnitSquare + "f a b c\nm light\n  rd 0.5\nf a c d\nm light\nf b c d\n");
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[1].name, "light #2");
  EXPECT_EQ(s.polygons[0].material, 0);
  EXPECT_EQ(s.polygons[1].material, 1);
  EXPECT_EQ(s.polygons[2].material, 1);
}

TEST(MgfImport, IgnoredTermsAreWarnedAboutOnceWithTheirCount) {
  std::vector<std::string> warnings;
  const Scene s = importMgfText(
      kUnitSquare + "  rs 0.1 0.05\n  sides 2\nm other =\n  rs 0.2 0\nf a b c\n", &warnings);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("line 11: rs ignored: specular reflectance"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("(2 times)"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[1].find("line 12: sides 2 ignored: radmesh surfaces are one-sided"), std::string::npos)
      << warnings[1];
}

// sides 1 asks for the one side radmesh gives every surface: nothing to warn of (it was "ignored").
TEST(MgfImport, SidesOneIsWhatRadmeshDoes) {
  std::vector<std::string> warnings;
  importMgfText(kUnitSquare + "  sides 1\nf a b c\n", &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
}

// A byte-order mark (some Windows editors write one) is not part of the first entity: it read as
// "unknown entity '\xEF\xBB\xBFm'", and the material it defined was then "not defined".
TEST(MgfImport, AByteOrderMarkIsSkipped) {
  std::vector<std::string> warnings;
  const Scene s = importMgfText("\xEF\xBB\xBF" + kUnitSquare + "f a b c d\n", &warnings);
  EXPECT_EQ(s.polygons.size(), 1u);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
}

// Lines ending in CR alone (classic Mac OS) read as lines, not as one line holding the whole file
// ("contains no polygons"); Windows' CR LF as before.
TEST(MgfImport, LinesEndingInCrAloneOrCrLfAreRead) {
  std::string mac, windows;
  for (const char c : kUnitSquare + "f a b c d\n") {
    mac += c == '\n' ? '\r' : c;
    if (c == '\n') windows += '\r';
    windows += c;
  }
  for (const std::string& text : {mac, windows}) {
    std::vector<std::string> warnings;
    const Scene s = importMgfText(text, &warnings);
    EXPECT_EQ(s.polygons.size(), 1u);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
  }
}

TEST(MgfImport, OriginsNameLineEntityAndObject) {
  const Scene s = importMgfText(kUnitSquare + "o desk\no top\nf a b c\no\no\n");
  ASSERT_EQ(s.polygons.size(), 1u);
  EXPECT_EQ(s.polygons[0].origin, "line 13: f (object 'desk/top')");
}

}  // namespace
}  // namespace radmesh
