#include "solver/io/mgf_color.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/io/mgf_error.h"

namespace radmesh {

namespace {

Xyz chromaticityToXyz(double x, double y) { return {x / y, 1.0, (1.0 - x - y) / y}; }

// RGB -> XYZ: each primary's chromaticity scaled so that R = G = B = 1 is the white point
// (the standard construction, e.g. SMPTE RP 177).
glm::dmat3 rgbToXyz() {
  const glm::dmat3 primaries(chromaticityToXyz(0.64, 0.33),   // Rec. 709 red
                             chromaticityToXyz(0.30, 0.60),   // green
                             chromaticityToXyz(0.15, 0.06));  // blue
  const Xyz scale = glm::inverse(primaries) * kMgfNeutral;
  return glm::dmat3(primaries[0] * scale.x, primaries[1] * scale.y, primaries[2] * scale.z);
}

const glm::dmat3& toXyz() {
  static const glm::dmat3 m = rgbToXyz();
  return m;
}

const glm::dmat3& toRgb() {
  static const glm::dmat3 m = glm::inverse(rgbToXyz());
  return m;
}

// CIE 1931 2-degree colour matching functions as the multi-lobe Gaussian fit of Wyman, Sloan and
// Shirley, "Simple Analytic Approximations to the CIE XYZ Color Matching Functions", JCGT 2(2),
// 2013, eq. 2: within the spread of the observers the standard was built from, and no table to
// mistype. Each lobe has a different width left and right of its peak.
double lobe(double nm, double peak, double widthBelow, double widthAbove) {
  const double t = (nm - peak) / (nm < peak ? widthBelow : widthAbove);
  return std::exp(-0.5 * t * t);
}

Xyz observer(double nm) {
  return {1.056 * lobe(nm, 599.8, 37.9, 31.0) + 0.362 * lobe(nm, 442.0, 16.0, 26.7) -
              0.065 * lobe(nm, 501.1, 20.4, 26.2),
          0.821 * lobe(nm, 568.8, 46.9, 40.5) + 0.286 * lobe(nm, 530.9, 16.3, 31.1),
          1.217 * lobe(nm, 437.0, 11.8, 36.0) + 0.681 * lobe(nm, 459.0, 26.0, 13.8)};
}

// Outside 360-830 nm the observer is below 1e-4 of its peak.
constexpr double kVisibleMinNm = 360.0;
constexpr double kVisibleMaxNm = 830.0;

template <class Spectrum>
Xyz integrate(double minNm, double maxNm, Spectrum spectrum) {
  Xyz sum{0.0};
  for (double nm = std::ceil(std::max(minNm, kVisibleMinNm)); nm <= std::min(maxNm, kVisibleMaxNm);
       nm += 1.0)
    sum += spectrum(nm) * observer(nm);
  return sum;
}

Xyz unitLuminance(const Xyz& xyz, const std::string& what) {
  if (!(xyz.y > 0.0) || !std::isfinite(xyz.x + xyz.y + xyz.z))
    throw MgfError(what + " gives no visible light (luminance 0)",
                   "give values that are non-zero somewhere in 380-780 nm");
  return xyz / xyz.y;
}

}  // namespace

Xyz xyzFromChromaticity(double x, double y) {
  if (x < 0.0 || y <= 0.0 || x + y > 1.0)
    throw MgfError(fmt::format("chromaticity ({:g}, {:g}) is impossible (needs x >= 0, y > 0, x + y <= 1)", x, y),
                   "give CIE 1931 x y of a real colour, e.g. cxy 0.333 0.333 for white");
  return chromaticityToXyz(x, y);
}

Xyz xyzFromSpectrum(double minNm, double maxNm, const std::vector<double>& samples) {
  if (samples.size() < 2 || !(maxNm > minNm))
    throw MgfError("a spectrum needs l_min < l_max and at least two values",
                   "write cspec l_min l_max v1 v2 ... with wavelengths in nm");
  for (const double v : samples)
    if (v < 0.0)
      throw MgfError(fmt::format("spectrum value {:g} is negative", v), "give cspec values >= 0 (relative power)");
  const double step = (maxNm - minNm) / static_cast<double>(samples.size() - 1);
  const auto interpolated = [&](double nm) {
    const double at = (nm - minNm) / step;
    const size_t i = std::min(static_cast<size_t>(at), samples.size() - 2);
    const double f = at - static_cast<double>(i);
    return samples[i] * (1.0 - f) + samples[i + 1] * f;
  };
  return unitLuminance(integrate(minNm, maxNm, interpolated), "the spectrum");
}

Xyz xyzFromTemperature(double kelvin) {
  // MGF's reference parser refuses a black body below 1000 K (MG_EILL) and sets no upper bound.
  constexpr double kCoolestKelvin = 1000.0;
  if (!(kelvin >= kCoolestKelvin))
    throw MgfError(fmt::format("colour temperature {:g} K is below {:g} K", kelvin, kCoolestKelvin),
                   fmt::format("give cct a temperature in kelvin from {:g} up, e.g. cct 3000", kCoolestKelvin));
  // Planck's law up to the constant factor kelvin / c2 (c2, the second radiation constant, in nm K):
  // nm^-4 x / (e^x - 1) with x = c2 / (nm kelvin) stays finite however hot the body, tending to
  // Rayleigh-Jeans' nm^-4 where x underflows.
  const auto planck = [kelvin](double nm) {
    const double x = 1.438776877e7 / (nm * kelvin);
    return std::pow(nm / 1000.0, -4.0) * (x > 0.0 ? x / std::expm1(x) : 1.0);
  };
  return unitLuminance(integrate(kVisibleMinNm, kVisibleMaxNm, planck),
                       fmt::format("a black body at {:g} K", kelvin));
}

Xyz mixColors(const std::vector<double>& weights, const std::vector<Xyz>& colors) {
  Xyz sum{0.0};
  for (size_t i = 0; i < weights.size(); ++i) {
    if (weights[i] < 0.0)
      throw MgfError(fmt::format("cmix weight {:g} is negative", weights[i]),
                     "give each colour a relative brightness >= 0");
    sum += weights[i] * colors[i] / colors[i].y;
  }
  if (!std::isfinite(sum.x + sum.y + sum.z))
    throw MgfError("the cmix weights add up past the largest number", "give relative weights, e.g. 1 and 3");
  return unitLuminance(sum, "the mix (all weights zero)");
}

Rgb linearRgb(const Xyz& xyz) { return toRgb() * xyz; }

double luminance(const Rgb& rgb) { return (toXyz() * rgb).y; }

Rgb fitRgb(const Xyz& xyz, double y, double ceiling, ColorRepair* repair) {
  if (repair) *repair = ColorRepair::kNone;
  if (!(y > 0.0)) return Rgb(0.0);
  Rgb unit = linearRgb(xyz / xyz.y);
  // Neutral to within what the matrices' rounding and white written to six digits (cxy 0.333333
  // 0.333333: 3e-6) leave: exactly grey, so that a grey scene is solved in one channel, not three.
  constexpr double kNeutral = 1e-5;
  if (glm::all(glm::lessThanEqual(glm::abs(unit - Rgb(1.0)), Rgb(kNeutral)))) unit = Rgb(1.0);
  // Along unit(t) = 1 + t (unit - 1) luminance stays 1; take the largest t <= 1 that fits: no
  // channel below 0 (the gamut) and none above the ceiling. A neutral colour's channels come out of
  // the colour matrices 1 +- rounding: at a ceiling of y (rd 0.99) that is not an excess.
  constexpr double kRounding = 1e-12;
  double inGamut = 1.0;
  double underCeiling = 1.0;
  for (int c = 0; c < 3; ++c) {
    const double d = unit[c] - 1.0;
    if (d < 0.0) inGamut = std::min(inGamut, 1.0 / -d);
    if (d > kRounding) underCeiling = std::min(underCeiling, (ceiling / y - 1.0) / d);
  }
  const double t = std::max(std::min(inGamut, underCeiling), 0.0);
  if (repair) {
    // A repair worth a warning changes a channel by more than a thousandth (a primary's zero
    // channels come out of the matrices as -1e-17).
    const Rgb off = glm::abs(unit - Rgb(1.0));
    const double spread = std::max({off.r, off.g, off.b});
    if ((1.0 - inGamut) * spread > kWorthAWarning)
      *repair = ColorRepair::kOutsideGamut;
    else if ((1.0 - t) * spread > kWorthAWarning && spread > kNearNeutral)
      *repair = ColorRepair::kTooSaturated;
  }
  return y * (Rgb(1.0) + t * (unit - Rgb(1.0)));
}

Rgb mgfReflectance(double rd, const Xyz& xyz, ColorRepair* repair) {
  return fitRgb(xyz, rd, std::max(rd, kHighestReflectance), repair);
}

Rgb mgfEmittance(double ed, const Xyz& xyz, ColorRepair* repair) {
  return fitRgb(xyz, ed / kWhiteEfficacyLmPerW, std::numeric_limits<double>::infinity(), repair);
}

}  // namespace radmesh
