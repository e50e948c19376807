#include "solver/projection/single_plane.h"

#include <cmath>
#include <numbers>

namespace radmesh {

double singlePlaneCapturedFraction(double ratio) {
  const double s = ratio / std::sqrt(1.0 + ratio * ratio);
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
  scaleToCapturedFraction(surface, singlePlaneCapturedFraction(ratio));
  return surface;
}

}  // namespace radmesh
