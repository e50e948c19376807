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
  // A plane that misses nearly every shot solves nothing: the ledger would book it all as lost.
  if (!(closedForm >= kLeastCapturedFraction))
    throw OptionError(fmt::format("--ratio {}: the plane catches {:.2g}% of each shot, so the solve would lose nearly "
                                  "all its light; give --ratio 0.1 or more (3, the paper's, catches {:.1f}%)",
                                  ratio, 100.0 * closedForm, 100.0 * singlePlaneCapturedFraction(3.0)));
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
