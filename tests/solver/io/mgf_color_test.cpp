// CIE colour to linear RGB: the white point, the primaries, spectra through the observer fit,
// and luminance-preserving gamut fitting.
#include "solver/io/mgf_color.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "solver/io/mgf_error.h"
#include "tests/solver/io/mgf_test_scene.h"

namespace radmesh {
namespace {

glm::dvec2 chromaticity(const Xyz& c) { return {c.x / (c.x + c.y + c.z), c.y / (c.x + c.y + c.z)}; }

TEST(MgfColor, EqualEnergyWhiteIsEqualRgb) {
  // The white point is E (x = y = 1/3): MGF's neutral colour.
  const Rgb white = linearRgb(xyzFromChromaticity(1.0 / 3.0, 1.0 / 3.0));
  EXPECT_NEAR(white.r, 1.0, 1e-12);
  EXPECT_NEAR(white.g, 1.0, 1e-12);
  EXPECT_NEAR(white.b, 1.0, 1e-12);
  // D65 is then slightly blue: B > G > R.
  const Rgb d65 = linearRgb(xyzFromChromaticity(0.3127, 0.3290));
  EXPECT_GT(d65.b, d65.g);
  EXPECT_GT(d65.g, d65.r);
}

TEST(MgfColor, Rec709PrimariesAreSingleChannels) {
  const Rgb red = linearRgb(xyzFromChromaticity(0.64, 0.33));
  const Rgb green = linearRgb(xyzFromChromaticity(0.30, 0.60));
  const Rgb blue = linearRgb(xyzFromChromaticity(0.15, 0.06));
  EXPECT_NEAR(red.g, 0.0, 1e-12);
  EXPECT_NEAR(red.b, 0.0, 1e-12);
  EXPECT_NEAR(green.r, 0.0, 1e-12);
  EXPECT_NEAR(blue.g, 0.0, 1e-12);
  // Each at luminance 1: 1 / its luminance weight; the weights of white sum to 1.
  EXPECT_NEAR(luminance(red), 1.0, 1e-12);
  EXPECT_NEAR(luminance(Rgb(1.0)), 1.0, 1e-12);
  EXPECT_NEAR(1.0 / red.r + 1.0 / green.g + 1.0 / blue.b, 1.0, 1e-12);
}

TEST(MgfColor, SpectraGoThroughTheStandardObserver) {
  // A flat spectrum is equal-energy white; black bodies land on the Planckian locus (CIE
  // illuminant A is 2856 K at (0.4476, 0.4074)); the analytic observer fit is good to ~0.002.
  const glm::dvec2 flat = chromaticity(xyzFromSpectrum(380, 780, {1, 1, 1, 1, 1}));
  EXPECT_NEAR(flat.x, 1.0 / 3.0, 2e-3);
  EXPECT_NEAR(flat.y, 1.0 / 3.0, 2e-3);
  const glm::dvec2 a = chromaticity(xyzFromTemperature(2856));
  EXPECT_NEAR(a.x, 0.4476, 2e-3);
  EXPECT_NEAR(a.y, 0.4074, 2e-3);
  const glm::dvec2 d = chromaticity(xyzFromTemperature(6504));
  EXPECT_NEAR(d.x, 0.3135, 2e-3);
  EXPECT_NEAR(d.y, 0.3236, 2e-3);
  EXPECT_DOUBLE_EQ(xyzFromTemperature(3000).y, 1.0);
  // However hot, a black body has a colour: the locus ends at about (0.240, 0.234) (Rayleigh-Jeans),
  // where a temperature past the largest double once overflowed into "no visible light".
  const glm::dvec2 hottest = chromaticity(xyzFromTemperature(1e308));
  EXPECT_NEAR(hottest.x, 0.2399, 3e-3);
  EXPECT_NEAR(hottest.y, 0.2342, 3e-3);
  EXPECT_NEAR(glm::distance(hottest, chromaticity(xyzFromTemperature(1e12))), 0.0, 1e-6);
  EXPECT_THROW(xyzFromSpectrum(900, 1000, {1, 1}), MgfError);  // infrared: no luminance
}

// MGF's reference parser refuses a black body below 1000 K (MG_EILL), which radmesh had read down
// to the temperature that leaves no visible light; it sets no upper bound.
TEST(MgfColor, BlackBodiesBelow1000KAreRefused) {
  EXPECT_DOUBLE_EQ(xyzFromTemperature(1000.0).y, 1.0);
  for (const double kelvin : {999.9, 1.0, 0.0, -5.0}) {
    try {
      xyzFromTemperature(kelvin);
      ADD_FAILURE() << kelvin << " K was accepted";
    } catch (const MgfError& e) {
      EXPECT_EQ(std::string(e.what()), fmt::format("colour temperature {:g} K is below 1000 K", kelvin));
      EXPECT_EQ(e.fix(), "give cct a temperature in kelvin from 1000 up, e.g. cct 3000");
    }
  }
}

TEST(MgfColor, MixingPrimariesByTheirLuminanceWeightsGivesWhite) {
  const Rgb weights = 1.0 / Rgb(linearRgb(xyzFromChromaticity(0.64, 0.33)).r,
                                linearRgb(xyzFromChromaticity(0.30, 0.60)).g,
                                linearRgb(xyzFromChromaticity(0.15, 0.06)).b);
  const Rgb mixed = linearRgb(mixColors({weights.r, weights.g, weights.b},
                                        {xyzFromChromaticity(0.64, 0.33), xyzFromChromaticity(0.30, 0.60),
                                         xyzFromChromaticity(0.15, 0.06)}));
  EXPECT_NEAR(glm::length(mixed - Rgb(1.0)), 0.0, 1e-12);
}

TEST(MgfColor, OutOfGamutReflectanceIsDesaturatedKeepingLuminance) {
  // corridor.mgf's red door: cxy 0.75 0.10 lies outside the spectral locus.
  ColorRepair repair = ColorRepair::kNone;
  const Rgb rho = mgfReflectance(0.29, xyzFromChromaticity(0.75, 0.10), &repair);
  EXPECT_EQ(repair, ColorRepair::kOutsideGamut);
  EXPECT_NEAR(luminance(rho), 0.29, 1e-12);
  for (int c = 0; c < 3; ++c) {
    EXPECT_GE(rho[c], 0.0);
    EXPECT_LE(rho[c], kHighestReflectance + 1e-12);
  }
  // Desaturated no further than needed: a channel sits on a bound.
  EXPECT_TRUE(std::abs(std::max({rho.r, rho.g, rho.b}) - kHighestReflectance) < 1e-12 ||
              std::abs(std::min({rho.r, rho.g, rho.b})) < 1e-12);
  const Rgb grey = mgfReflectance(0.5, kMgfNeutral, &repair);
  EXPECT_EQ(repair, ColorRepair::kNone);
  EXPECT_NEAR(glm::length(grey - Rgb(0.5)), 0.0, 1e-12);
}

// rd 0.99 puts the ceiling at the luminance itself: a neutral colour's channels, 1 up to rounding,
// must not count as outside the gamut (they did, and --strict refused the file).
TEST(MgfColor, NeutralAtTheHighestReflectanceIsNotDesaturated) {
  ColorRepair repair = ColorRepair::kTooSaturated;
  const Rgb rho = mgfReflectance(kHighestReflectance, kMgfNeutral, &repair);
  EXPECT_EQ(repair, ColorRepair::kNone);
  EXPECT_NEAR(glm::length(rho - Rgb(kHighestReflectance)), 0.0, 1e-12);
  const std::string face = "v a =\n p 0 0 0\nv b =\n p 1 0 0\nv c =\n p 0 1 0\n";
  std::vector<std::string> warnings;
  test::importMgfText("m white =\n  c\n  rd 0.99\n" + face + "f a b c\n", &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  // White to six digits is white: rounding is no repair to warn of (--strict refused it).
  test::importMgfText("m white =\n  c\n    cxy 0.333333 0.333333\n  rd 0.99\n" + face + "f a b c\n", &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  // A colour truly outside the gamut still warns at the same reflectance.
  test::importMgfText("m red =\n  c\n    cxy 0.75 0.10\n  rd 0.99\n" + face + "f a b c\n", &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("material 'red': its colour lies outside the Rec. 709 gamut"), std::string::npos)
      << warnings[0];
}

// MGF's white to three digits (cxy 0.333 0.333: blue 1.0035 at luminance 1) and D65 at rd 0.99 had
// a channel past the ceiling and warned "outside the Rec. 709 gamut" (--strict refused the file). A
// near-neutral colour never warns at any rd MGF allows; a saturated one still does.
TEST(MgfColor, NearNeutralColoursNeverWarnAtAnyLegalReflectance) {
  const std::string face = "v a =\n p 0 0 0\nv b =\n p 1 0 0\nv c =\n p 0 1 0\nf a b c\n";
  for (const std::string white : {"0.333 0.333", "0.3127 0.3290", "0.3457 0.3585", "0.337 0.337", "0.3632 0.3420"}) {
    for (const double rd : {0.5, 0.9, 0.95, 0.99, 1.0}) {
      std::vector<std::string> warnings;
      const Scene s =
          test::importMgfText(fmt::format("m white =\n  c\n    cxy {}\n  rd {}\n", white, rd) + face, &warnings);
      ASSERT_EQ(warnings.size(), rd == 1.0 ? 1u : 0u)
          << white << " rd " << rd << ": " << (warnings.empty() ? "" : warnings.back());
      if (rd == 1.0) {
        EXPECT_NE(warnings[0].find("rd 1 lowered to 0.99"), std::string::npos) << warnings[0];
      }
      const Rgb rho = s.materials.at(0).rho;
      EXPECT_NEAR(luminance(rho), std::min(rd, kHighestReflectance), 1e-12) << white << " rd " << rd;
      EXPECT_LE(std::max({rho.r, rho.g, rho.b}), kHighestReflectance + 1e-12) << white << " rd " << rd;
      EXPECT_GE(std::min({rho.r, rho.g, rho.b}), 0.0) << white << " rd " << rd;
    }
  }
  ColorRepair repair = ColorRepair::kOutsideGamut;
  mgfReflectance(kHighestReflectance, xyzFromChromaticity(0.3127, 0.3290), &repair);
  EXPECT_EQ(repair, ColorRepair::kNone);
  // The one warning for a material `name` of colour `cxy` at `rd`, from its first face, line 11.
  const auto onlyWarning = [&](const std::string& name, const std::string& cxy, const std::string& rd) {
    std::vector<std::string> warnings;
    test::importMgfText("m " + name + " =\n  c\n    cxy " + cxy + "\n  rd " + rd + "\n" + face, &warnings);
    EXPECT_EQ(warnings.size(), 1u);
    return warnings.empty() ? std::string() : warnings[0];
  };
  // The red primary lies in the gamut, but at rd 0.5 its red channel would be 1.95.
  const std::string red = onlyWarning("red", "0.64 0.33", "0.5");
  EXPECT_NE(red.find("scene.mgf: line 11: material 'red': its colour is too saturated for rd 0.5: a channel would "
                     "pass 0.99; desaturated toward grey, keeping its luminance"),
            std::string::npos)
      << red;
  // corridor.mgf's door lies outside the gamut, at any rd.
  const std::string door = onlyWarning("door", "0.75 0.10", "0.29");
  EXPECT_NE(door.find("scene.mgf: line 11: material 'door': its colour lies outside the Rec. 709 gamut; desaturated "
                      "toward grey, keeping its luminance"),
            std::string::npos)
      << door;
}

TEST(MgfColor, EmittanceIsLumensOver179PerChannel) {
  ColorRepair repair = ColorRepair::kOutsideGamut;
  const Rgb e = mgfEmittance(179.0 * 4.0, kMgfNeutral, &repair);
  EXPECT_EQ(repair, ColorRepair::kNone);
  EXPECT_NEAR(glm::length(e - Rgb(4.0)), 0.0, 1e-12);
}

TEST(MgfColor, MgfNeutralWhiteGivesEqualReflectance) {
  const Scene s = test::importMgfText(
      "m wall =\n  c\n    cxy 0.333333 0.333333\n  rd 0.6\nv a =\n p 0 0 0\nv b =\n p 1 0 0\n"
      "v c =\n p 0 1 0\nf a b c\n");
  ASSERT_EQ(s.materials.size(), 1u);
  // Exactly grey, as with no colour at all: the effects plan solves a grey scene in one channel, and
  // rounding (0.6000000000000002 in red) or six digits (3e-6) had switched colour on.
  EXPECT_EQ(s.materials[0].rho, Rgb(0.6));
  EXPECT_EQ(mgfReflectance(0.5, kMgfNeutral, nullptr), Rgb(0.5));
  EXPECT_EQ(mgfEmittance(100.0, xyzFromChromaticity(0.333333, 0.333333), nullptr), Rgb(100.0 / kWhiteEfficacyLmPerW));
  // A tint of a thousandth stays a tint.
  const Rgb tint = mgfReflectance(0.5, xyzFromChromaticity(0.3337, 0.3333), nullptr);
  EXPECT_NE(tint.r, tint.b);
}

TEST(MgfColor, SpectralAndMixedColoursReachTheMaterial) {
  // Incandescent (2856 K) is orange: R > G > B; a flat spectrum is grey; red and green mixed
  // by their luminance weights is yellow (B = 0) at the luminance rd.
  const std::string face = "v a =\n p 0 0 0\nv b =\n p 1 0 0\nv c =\n p 0 1 0\nf a b c\n";
  const Scene warm = test::importMgfText("m lamp =\n  c\n    cct 2856\n  rd 0.5\n" + face);
  const Rgb w = warm.materials.at(0).rho;
  EXPECT_GT(w.r, w.g);
  EXPECT_GT(w.g, w.b);
  EXPECT_NEAR(luminance(w), 0.5, 1e-12);
  const Scene flat = test::importMgfText("m grey =\n  c\n    cspec 380 780 2 2 2\n  rd 0.5\n" + face);
  EXPECT_NEAR(glm::length(flat.materials.at(0).rho - Rgb(0.5)), 0.0, 0.01);
  const Scene mixed = test::importMgfText(
      "c r =\n  cxy 0.64 0.33\nc g =\n  cxy 0.30 0.60\nm yellow =\n  c\n    cmix 1 r 1 g\n  rd 0.5\n" + face);
  const Rgb y = mixed.materials.at(0).rho;
  EXPECT_NEAR(y.b, 0.0, 1e-12);
  EXPECT_NEAR(luminance(y), 0.5, 1e-12);
  EXPECT_NEAR(y.r * luminance(Rgb(1, 0, 0)), y.g * luminance(Rgb(0, 1, 0)), 1e-12);  // equal shares
}

}  // namespace
}  // namespace radmesh
