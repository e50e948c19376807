#include "solver/projection/single_plane.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "solver/scene/scene_error.h"

namespace radmesh {

double singlePlaneCapturedFraction(double ratio) {
  const double s = 1.0 / std::sqrt(1.0 + 1.0 / (ratio * ratio));  // r / sqrt(1 + r^2), with no r^2 to overflow
  return 4.0 / std::numbers::pi * s * std::atan(s);
}

double singlePlaneDeltaFormFactor(double x, double y, double pixelArea) {
  const double q = x * x + y * y + 1.0;
  return pixelArea / (std::numbers::pi * q * q);
}

ProjectionFace singlePlaneFace(int resolution, double ratio) {
  ProjectionFace face;  // a along u, b along v, depth along n
  face.a0 = face.b0 = -ratio;
  face.a1 = face.b1 = ratio;
  face.width = face.height = resolution;
  return face;
}

ProjectionSurface makeSinglePlane(int resolution, double ratio) {
  ProjectionSurface surface;
  addFace(surface, singlePlaneFace(resolution, ratio), singlePlaneDeltaFormFactor);
  const double closedForm = singlePlaneCapturedFraction(ratio);
  scaleToCapturedFraction(surface, closedForm);
  // Pixels wide against the plane's height sample the form factor at their centres too coarsely:
  // scaling the table to the closed form would keep the total and put the light in the wrong places.
  if (!(std::abs(surface.tableSum - closedForm) <= kPlaneSamplingTolerance * closedForm))  // NaN too
    throw OptionError(fmt::format(
        "--ratio {} at --resolution {}: the plane's pixels, {:.3g} wide at height 1, are too coarse to sample the "
        "form factor (their delta form factors sum to {:.4f}, the closed form is {:.4f}); use --ratio {:.3g} or "
        "less, or a larger --resolution",
        ratio, resolution, 2.0 * ratio / resolution, surface.tableSum, closedForm, 0.3 * resolution));
  return surface;
}

}  // namespace radmesh
