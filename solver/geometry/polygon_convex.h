#pragma once
// Convex decomposition of a 2D polygon: ear clipping, then Hertel–Mehlhorn merging of the
// triangles back into convex pieces, so that a concave face is not cut into needless slivers.
#include <string>
#include <vector>

#include "solver/geometry/polygon_2d.h"

namespace radmesh {

// True when every vertex of the counter-clockwise polygon turns left or goes straight (within
// noiseM) and the boundary winds around once.
bool isConvex(const std::vector<Vec2>& ccw, double noiseM);

// Convex pieces (each counter-clockwise, as points) that tile `ccw`. Their total area equals the
// polygon's unless the polygon crosses itself: the caller compares the two.
std::vector<std::vector<Vec2>> convexPieces(const std::vector<Vec2>& ccw, double noiseM);

// The convex pieces that cover the counter-clockwise outline once (the outline itself when it is
// convex), with `crossing` empty; where the outline crosses or overlaps itself, `crossing` says how
// ("its convex parts cover 0.5 of its 1 projected square metres"). Concave outlines and holes
// reached through seams cover once.
std::vector<std::vector<Vec2>> convexCover(const std::vector<Vec2>& ccw, double noiseM, std::string& crossing);

}  // namespace radmesh
