#pragma once
// MGF colour (CIE 1931 chromaticity or spectrum) to the linear RGB the solver uses.
//
// Conventions (also in docs/scene-formats.md):
// - An MGF colour carries chromaticity only; its brightness comes from the rd/ed value it modifies.
//   A colour is held as CIE XYZ scaled to luminance Y = 1.
// - RGB is linear, with Rec. 709 / sRGB primaries and the equal-energy white E (x = y = 1/3) as
//   white point: MGF's neutral colour (its default, and the `cxy .333 .333` of every white wall)
//   maps to R = G = B = 1, so a white `rd 0.6` becomes rho (0.6, 0.6, 0.6), exactly: a colour within
//   1e-5 of white in every channel (white written to six digits) is taken as white.
// - Luminance is preserved: a colour of luminance Y has RGB whose Rec. 709/E luminance is Y.
// - Emittance: MGF's ed is luminous emittance in lm/m^2; it becomes radiant exitance in W/m^2 at
//   179 lm/W, the luminous efficacy of equal-energy white that Radiance (MGF's origin) uses.
//   Each RGB channel holds the exitance a white source of that brightness has, so a white
//   `ed 179` is E = (1, 1, 1) W/m^2.
// - Colours outside the gamut (and reflectances too bright in one channel) are desaturated toward
//   grey keeping their luminance, so rd and ed keep their photometric meaning.
#include <string>
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

using Xyz = glm::dvec3;  // CIE 1931 tristimulus values

inline const Xyz kMgfNeutral{1.0, 1.0, 1.0};  // equal-energy white at Y = 1

// Chromaticity (x, y) at Y = 1; throws MgfError unless x, y >= 0, y > 0 and x + y <= 1.
Xyz xyzFromChromaticity(double x, double y);

// A relative spectrum sampled evenly from minNm to maxNm (cspec), through the CIE 1931 observer,
// scaled to Y = 1; throws MgfError for fewer than two samples or no visible light.
Xyz xyzFromSpectrum(double minNm, double maxNm, const std::vector<double>& samples);

// A black body at `kelvin` (cct), scaled to Y = 1; throws MgfError below 1000 K.
Xyz xyzFromTemperature(double kelvin);

// cmix: colours (each at Y = 1) summed with weights that are relative luminances, scaled to Y = 1.
Xyz mixColors(const std::vector<double>& weights, const std::vector<Xyz>& colors);

// What fitting a colour into RGB did that is worth a warning. A repair that changes no channel by
// more than kWorthAWarning (of the luminance) is none: rounding, or white written to a few digits.
enum class ColorRepair {
  kNone,
  kOutsideGamut,  // a channel was below 0: the colour lies outside the Rec. 709 gamut
  kTooSaturated,  // in the gamut, but a channel passed the ceiling at this reflectance
};
inline constexpr double kWorthAWarning = 1e-3;
// A colour whose channels at luminance 1 all lie within this of 1 is near-neutral: a white
// (cxy 0.333 0.333, D65 0.3127 0.3290, D50, the off-white paint of the MGF specification). At a
// high rd (0.99) one of its channels passes the ceiling; it is desaturated there too, but only
// toward the grey it nearly is: no warning, at any rd MGF allows.
inline constexpr double kNearNeutral = 0.25;

// rho for `rd` in [0, 1) of colour `xyz`: luminance rd, channels in [0, max(rd,
// kHighestReflectance)] (where a saturated colour pushes one up, it stops there).
Rgb mgfReflectance(double rd, const Xyz& xyz, ColorRepair* repair);
// E in W/m^2 for `ed` lm/m^2 of colour `xyz`: channels >= 0, luminance ed / 179.
Rgb mgfEmittance(double ed, const Xyz& xyz, ColorRepair* repair);

// Linear RGB (Rec. 709 primaries, white E) of a colour; may be negative outside that gamut.
Rgb linearRgb(const Xyz& xyz);

// The Rec. 709 / E luminance of linear RGB (the Y row of the RGB-to-XYZ matrix).
double luminance(const Rgb& rgb);

// Colour `xyz` at luminance `y`, desaturated toward the grey of the same luminance as little as
// needed so that every channel lies in [0, ceiling] (ceiling >= y). Sets *repair to what it had to
// do, when worth a warning (see ColorRepair).
Rgb fitRgb(const Xyz& xyz, double y, double ceiling, ColorRepair* repair);

}  // namespace radmesh
