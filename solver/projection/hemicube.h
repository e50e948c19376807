#pragma once
// The hemi-cube (Cohen & Greenberg 1985): a top face N x N and four half faces N x N/2 around
// the shooter, together covering the whole hemisphere; nothing a shooter emits is left uncaught.
#include "solver/projection/projection_surface.h"

namespace radmesh {

// Delta form factor of a side-face pixel at (y, z), one unit out, of area dA (Cohen & Greenberg
// 1985): z dA / (pi (y^2+z^2+1)^2). The top face is a single plane of half-side 1.
double hemicubeSideDeltaFormFactor(double y, double z, double pixelArea);

ProjectionSurface makeHemicube(int resolution);

// The hemicube's faces: the top (N x N over [-1, 1]^2) and the upper halves of the four sides.
std::vector<ProjectionFace> hemicubeFaces(int resolution);
// A whole cube around a point, every face N x N: the top, the four full sides and the bottom.
std::vector<ProjectionFace> cubeFaces(int resolution);

}  // namespace radmesh
