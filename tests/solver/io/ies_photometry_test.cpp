// MGF's ies entity: LM-63 photometry integrated into the flux that leaves the luminaire's opening.
#include "solver/io/ies_photometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "solver/io/mgf_color.h"
#include "solver/io/mgf_import.h"
#include "solver/scene/scene_error.h"
#include "tests/solver/io/mgf_test_scene.h"
#include "tests/test_paths.h"

namespace radmesh {
namespace {

TEST(IesPhotometry, UniformIntensityIsTwoPiTimesItPerHemisphere) {
  const IesLuminaire lum = readIes(test::dataPath("ies/uniform.ies").string(), 3.0);
  EXPECT_NEAR(lum.downLumens, 3.0 * 200.0 * std::numbers::pi, 1e-9);
  EXPECT_NEAR(lum.upLumens, 3.0 * 200.0 * std::numbers::pi, 1e-9);
  EXPECT_EQ(lum.widthM, 0.5);
  EXPECT_EQ(lum.lengthM, 1.0);
  EXPECT_TRUE(lum.notes.empty());
}

TEST(IesPhotometry, TheMgfEntityEmitsTheFluxFromTheOpeningsTwoSides) {
  std::vector<std::string> warnings;
  const Scene s = importMgf(test::dataPath("ies/lamp.mgf").string(), &warnings);
  EXPECT_TRUE(warnings.empty());
  ASSERT_EQ(s.polygons.size(), 2u);
  for (const Polygon& p : s.polygons) {
    EXPECT_DOUBLE_EQ(polygonArea(p.vertices), 0.5);
    const Vec3 n = glm::normalize(newellNormal(p.vertices));
    const bool down = n.z < 0.0;
    EXPECT_EQ(std::abs(n.z), 1.0);
    for (const Vec3& v : p.vertices) EXPECT_EQ(v.z, 3.0);
    const Material& m = s.materials[p.material];
    EXPECT_EQ(m.name, down ? "ies uniform.ies (down)" : "ies uniform.ies (up)");
    // 400 pi lm leave each 0.5 m^2 side: exitance 800 pi lm/m^2, at 179 lm/W.
    EXPECT_NEAR(luminance(m.emittance), 800.0 * std::numbers::pi / kWhiteEfficacyLmPerW, 1e-9);
    EXPECT_EQ(m.rho, Rgb(0.0));
  }
}

TEST(IesPhotometry, ATruncatedFileIsRefusedNamingWhatIsMissing) {
  try {
    importMgf(test::dataPath("ies/truncated.mgf").string());
    ADD_FAILURE() << "a truncated IES file was accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.file(), test::dataPath("ies/truncated.ies").string());
    EXPECT_EQ(e.element(), "candela of horizontal angle 1, 3");
    EXPECT_NE(std::string(e.what()).find("the file ends early"), std::string::npos) << e.what();
  }
}

// The MGF specification's own luminaire (../shared): a 4 ft two-lamp fixture, direct/indirect.
TEST(IesPhotometry, TheSpecificationsExampleLuminaire) {
  RADMESH_REQUIRE_SHARED(ies, "scenes/mgf/examp1.ies");
  const IesLuminaire lum = readIes(ies.string(), 1.0);
  EXPECT_NEAR(lum.lengthM, 4.04 * 0.3048, 1e-12);
  EXPECT_NEAR(lum.widthM, 0.85 * 0.3048, 1e-12);
  // Both hemispheres lit, and less light out than its two 2900 lm lamps make.
  EXPECT_GT(lum.downLumens, 1000.0);
  EXPECT_GT(lum.upLumens, 1000.0);
  EXPECT_LT(lum.downLumens + lum.upLumens, 5800.0);
}

}  // namespace
}  // namespace radmesh
