// MGF's ies entity: LM-63 photometry integrated into the flux that leaves the luminaire's opening.
#include "solver/io/ies_photometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>
#include <utility>

#include "solver/io/mgf_color.h"
#include "solver/io/mgf_import.h"
#include "solver/scene/scene_error.h"
#include "tests/solver/io/gltf_test_file.h"  // TempDir
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

// An LM-63-2002 file of one lamp, type C, metres: `sizes` (width length height), then the vertical
// and horizontal angle counts and lists and the candela values in `photometry`.
std::string iesFile(const test::TempDir& dir, const std::string& name, const std::string& counts,
                    const std::string& photometry, const std::string& sizes = "0.5 1.0 0.0",
                    const std::string& factors = "1.0", const std::string& ballast = "1.0 1.0") {
  const std::string path = (dir / name).string();
  std::ofstream(path) << "IESNA:LM-63-2002\n[TEST] radmesh\nTILT=NONE\n1 1000 " << factors << " " << counts << " 1 2 "
                      << sizes << "\n" << ballast << " 100\n" << photometry << "\n";
  return path;
}

// 100 cd all round is 200 pi lm a hemisphere however the vertical angles fall: a span across the
// horizontal is cut there (0-180 in one span all went up, 0-60-120-180 gave 100 pi down).
TEST(IesPhotometry, ASpanAcrossTheHorizontalIsCutThere) {
  const test::TempDir dir;
  for (const auto& [counts, photometry] : {std::pair{"2 1", "0 180\n0\n100 100"},
                                           std::pair{"4 1", "0 60 120 180\n0\n100 100 100 100"},
                                           std::pair{"4 1", "0 45 135 180\n0\n100 100 100 100"}}) {
    const IesLuminaire lum = readIes(iesFile(dir, "span.ies", counts, photometry), 1.0);
    EXPECT_NEAR(lum.downLumens, 200.0 * std::numbers::pi, 1e-9) << photometry;
    EXPECT_NEAR(lum.upLumens, 200.0 * std::numbers::pi, 1e-9) << photometry;
  }
  // A linear ramp across it: I = 2 theta / pi cd from 0 to 2 over 0-180 degrees, each half's closed form.
  const IesLuminaire ramp = readIes(iesFile(dir, "ramp.ies", "2 1", "0 180\n0\n0 2"), 1.0);
  const double pi = std::numbers::pi;
  EXPECT_NEAR(ramp.downLumens, 2.0 * pi * (2.0 / pi), 1e-9);        // 2 pi * integral of (2t/pi) sin t, 0..pi/2
  EXPECT_NEAR(ramp.upLumens, 2.0 * pi * (2.0 - 2.0 / pi), 1e-9);    // the same over pi/2..pi
}

// What no photometry means is refused naming the number, where it had been read as light: negative
// candela or factors, angles out of order or range, counts that do not match the numbers.
TEST(IesPhotometry, NumbersNoLuminaireHasAreRefusedNamingThem) {
  const test::TempDir dir;
  const std::string uniform = "0 90 180\n0\n100 100 100";
  const struct {
    std::string path, element, says;
  } cases[] = {
      {iesFile(dir, "negcd.ies", "3 1", "0 90 180\n0\n100 -50 100"), "candela of horizontal angle 1, 2",
       "no light is negative"},
      {iesFile(dir, "negmult.ies", "3 1", uniform, "0.5 1.0 0.0", "-1"), "candela multiplier", "is -1"},
      {iesFile(dir, "zeroballast.ies", "3 1", uniform, "0.5 1.0 0.0", "1", "0 1"), "ballast factor", "is 0"},
      {iesFile(dir, "unsorted.ies", "3 1", "0 180 90\n0\n100 100 100"), "vertical angle 3", "must rise"},
      {iesFile(dir, "range.ies", "3 1", "0 90 360\n0\n100 100 100"), "vertical angle 3", "must rise from 0 to at most 180"},
      {iesFile(dir, "hunsorted.ies", "2 3", "0 180\n0 90 45\n1 1\n1 1\n1 1"), "horizontal angle 3", "must rise"},
      {iesFile(dir, "extra.ies", "2 1", "0 90 180\n0\n100 100 100"), "candela values", "more numbers"},
      {iesFile(dir, "dark.ies", "2 1", "0 180\n0\n0 0"), "candela values", "are all zero"},
  };
  for (const auto& c : cases) {
    try {
      readIes(c.path, 1.0);
      ADD_FAILURE() << c.path << " was accepted";
    } catch (const SceneError& e) {
      EXPECT_EQ(e.element(), c.element) << e.what();
      EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
    }
  }
}

// A multiplier past any real luminaire is refused on the ies line, saying what to check: the
// scene's emitter check had named a material and asked for an emittance the file never gave.
TEST(IesPhotometry, AFluxPastWhatRadmeshTrustsIsRefusedOnTheIesLine) {
  const test::TempDir dir;
  iesFile(dir, "uniform.ies", "3 1", "0 90 180\n0\n100 100 100");
  const std::pair<std::string, std::string> multipliers[] = {{"1e308", "1e+308"}, {"1e200", "1e+200"}, {"1e-200", "1e-200"}};
  for (const auto& [m, shown] : multipliers) {
    const std::string path = (dir / ("lamp" + m + ".mgf")).string();
    std::ofstream(path) << "ies uniform.ies -m " << m << " -t 0 0 3\n";
    try {
      importMgf(path);
      ADD_FAILURE() << "-m " << m << " was accepted";
    } catch (const SceneError& e) {
      EXPECT_EQ(e.file(), path);
      EXPECT_EQ(e.element(), "line 1: ies");
      const std::string what = e.what();
      EXPECT_NE(what.find("uniform.ies sends "), std::string::npos) << what;
      EXPECT_NE(what.find("outside the 1e-30 to 1e+30 W/m^2 radmesh trusts"), std::string::npos) << what;
      EXPECT_NE(what.find("(fix: check -m (here " + shown + ")"), std::string::npos) << what;
      EXPECT_NE(what.find("and the candela multiplier and values in " + (dir / "uniform.ies").string()),
                std::string::npos) << what;
    }
  }
}

// LM-63-2002 marks rounded openings by negative sizes: a length or height below zero is its size,
// not a luminaire turned inside out (its faces looked at each other).
TEST(IesPhotometry, NegativeLengthAndHeightAreSizes) {
  const test::TempDir dir;
  const IesLuminaire lum = readIes(iesFile(dir, "round.ies", "2 1", "0 180\n0\n100 100", "0.5 -1.0 -0.2"), 1.0);
  EXPECT_EQ(lum.lengthM, 1.0);
  EXPECT_EQ(lum.heightM, 0.2);
  EXPECT_EQ(lum.widthM, 0.5);
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
