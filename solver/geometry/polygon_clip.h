#pragma once
// Cutting convex polygons along axis-parallel lines: the grid slicing of the paper's section 1.6,
// done in a polygon's own 2D frame.
#include <vector>

#include "solver/geometry/polygon_2d.h"

namespace radmesh {

// Splits a convex polygon at the line p[axis] = value into the parts below and above it (either
// may come back empty). Vertices within noiseM of the line count as on it, so no sliver is cut off
// a vertex that merely rounds to one side. The cut points do not depend on the edge's direction,
// so the neighbouring piece across a shared edge gets the same points.
void splitConvex(const std::vector<Vec2>& convex, int axis, double value, double noiseM,
                 std::vector<Vec2>& below, std::vector<Vec2>& above);

// Cuts a convex polygon at every line x = i * cellM and y = j * cellM (integers i, j) that crosses
// it, giving pieces within one grid cell each: convex, counter-clockwise, column by column.
std::vector<std::vector<Vec2>> sliceByGrid(const std::vector<Vec2>& convex, double cellM, double noiseM);

// Fans a convex k-gon into convex quads (0,1,2,3), (0,3,4,5), ... and, for odd k, a last triangle:
// as few patches as the paper's "triangles or convex quadrilaterals" allow.
std::vector<std::vector<Vec2>> fanIntoQuads(const std::vector<Vec2>& convex);

}  // namespace radmesh
