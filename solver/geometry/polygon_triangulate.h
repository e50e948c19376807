#pragma once
// Ear-clipping triangulation of a simple or weakly simple polygon: one that may touch itself at
// vertices and reach its holes through zero-width seams, as MGF faces do.
#include <array>
#include <vector>

#include "solver/geometry/polygon_2d.h"

namespace radmesh {

// Triangles as indices into `ccw` (a counter-clockwise polygon), each counter-clockwise. Vertices
// within `noiseM` of the line through their neighbours (collinear, repeated, or zero-width spikes)
// are dropped without a triangle, as they enclose no area. A polygon that crosses itself yields
// triangles whose total area differs from signedArea(ccw): the caller checks that sum.
std::vector<std::array<int, 3>> triangulatePolygon(const std::vector<Vec2>& ccw, double noiseM);

}  // namespace radmesh
