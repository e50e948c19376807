#pragma once
// The single plane (the paper's section 1.5; Recker et al. 1990): one square of half-side r at
// height 1 above the shooter, N x N pixels, catching most of a diffuse shooter's power.
#include "solver/projection/projection_surface.h"

namespace radmesh {

// Closed form of the form factor from a differential area to a centred, parallel square of
// half-side r at height 1: (4/pi) s atan(s), s = r / sqrt(1 + r^2). r = 3 gives 0.91688.
double singlePlaneCapturedFraction(double ratio);

// Delta form factor of a pixel of area dA on a plane at height 1, centred at (x, y):
// dA / (pi (x^2+y^2+1)^2). The hemicube's top face is such a plane too.
double singlePlaneDeltaFormFactor(double x, double y, double pixelArea);

// The plane's face: N x N pixels over [-r, r]^2, a along u, b along v.
ProjectionFace singlePlaneFace(int resolution, double ratio);

// Throws OptionError naming --ratio and --resolution when the pixels' delta form factors sum to
// more than kPlaneSamplingTolerance away from the closed form: pixels too wide to sample it; and
// naming --ratio when the plane catches under kLeastCapturedFraction of a shot (r below 0.089).
inline constexpr double kPlaneSamplingTolerance = 0.01;
inline constexpr double kLeastCapturedFraction = 0.01;
ProjectionSurface makeSinglePlane(int resolution, double ratio);

}  // namespace radmesh
