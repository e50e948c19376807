#include "solver/projection/hemicube.h"

#include <numbers>

#include "solver/projection/single_plane.h"

namespace radmesh {

double hemicubeSideDeltaFormFactor(double y, double z, double pixelArea) {
  const double q = y * y + z * z + 1.0;
  return z * pixelArea / (std::numbers::pi * q * q);
}

namespace {

// A side face looks along +-u or +-v: a runs along the other horizontal axis, b up the normal.
ProjectionFace sideFace(int depthAxis, double depthSign, int resolution) {
  ProjectionFace face;
  face.axis = {depthAxis == 0 ? 1 : 0, 2, depthAxis};
  face.sign = {1.0, 1.0, depthSign};
  face.b0 = 0.0;
  face.width = resolution;
  face.height = (resolution + 1) / 2;  // the upper half; an odd N rounds up
  return face;
}

}  // namespace

ProjectionSurface makeHemicube(int resolution) {
  ProjectionSurface surface;
  addFace(surface, singlePlaneFace(resolution, 1.0), singlePlaneDeltaFormFactor);
  for (int axis : {0, 1})
    for (double sign : {1.0, -1.0})
      addFace(surface, sideFace(axis, sign, resolution), hemicubeSideDeltaFormFactor);
  scaleToCapturedFraction(surface, 1.0);  // the whole hemisphere
  return surface;
}

}  // namespace radmesh
