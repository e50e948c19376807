#include "solver/projection/hemicube.h"

#include <numbers>
#include <vector>

#include "solver/projection/single_plane.h"

namespace radmesh {

double hemicubeSideDeltaFormFactor(double y, double z, double pixelArea) {
  const double q = y * y + z * z + 1.0;
  return z * pixelArea / (std::numbers::pi * q * q);
}

namespace {

// A side face looks along +-u or +-v: a runs along the other horizontal axis, b up the normal;
// the upper half (b from 0 to 1), or the whole side.
ProjectionFace sideFace(int depthAxis, double depthSign, int resolution, bool whole) {
  ProjectionFace face;
  face.axis = {depthAxis == 0 ? 1 : 0, 2, depthAxis};
  face.sign = {1.0, 1.0, depthSign};
  face.b0 = whole ? -1.0 : 0.0;
  face.width = resolution;
  face.height = whole ? resolution : (resolution + 1) / 2;  // the upper half: an odd N rounds up
  return face;
}

std::vector<ProjectionFace> facesAround(int resolution, bool wholeCube) {
  std::vector<ProjectionFace> faces{singlePlaneFace(resolution, 1.0)};
  for (int axis : {0, 1})
    for (double sign : {1.0, -1.0}) faces.push_back(sideFace(axis, sign, resolution, wholeCube));
  if (wholeCube) {
    ProjectionFace bottom = singlePlaneFace(resolution, 1.0);
    bottom.sign = {1.0, -1.0, -1.0};
    faces.push_back(bottom);
  }
  return faces;
}

}  // namespace

std::vector<ProjectionFace> hemicubeFaces(int resolution) { return facesAround(resolution, false); }
std::vector<ProjectionFace> cubeFaces(int resolution) { return facesAround(resolution, true); }

ProjectionSurface makeHemicube(int resolution) {
  ProjectionSurface surface;
  const std::vector<ProjectionFace> faces = hemicubeFaces(resolution);
  addFace(surface, faces[0], singlePlaneDeltaFormFactor);
  for (size_t f = 1; f < faces.size(); ++f) addFace(surface, faces[f], hemicubeSideDeltaFormFactor);
  scaleToCapturedFraction(surface, 1.0);  // the whole hemisphere
  return surface;
}

}  // namespace radmesh
