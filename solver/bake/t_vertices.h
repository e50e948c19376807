#pragma once
// T-vertices: a corner of one patch (or element) that lies inside an edge of another, where a
// split element meets an unsplit one, or patches of different sizes meet (furniture against a
// wall, coplanar neighbours meshed at different sizes). Drawn as they are, the long edge and the
// short ones beside it are rasterised apart, and pixels between them show what lies behind (a
// crack). Resolved over generic convex outlines: the points of neighbours found on an outline's
// edges join its triangulation (buildDisplayMesh, solver/bake/display_radiosity.h).
#include <array>
#include <span>
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

struct EdgePoint {
  int edge = 0;     // between the outline's corners edge and edge + 1 (mod their count)
  double t = 0.0;   // where along the edge, in (0, 1)
  int point = 0;    // index into the points searched
};

// For each outline (its corners counter-clockwise), the points that lie inside one of its edges:
// within toleranceM of the edge and farther than toleranceM from both its ends. Listed around the
// outline (by edge, then t); of coincident points (within toleranceM), the first only.
std::vector<std::vector<EdgePoint>> findEdgePoints(std::span<const std::span<const Vec3>> outlines,
                                                   std::span<const Vec3> points, double toleranceM);

// Triangles over a convex outline's ring: its corners (corner[i] true) and, between them, points
// inside its edges, counter-clockwise. As ring indices, counter-clockwise and none degenerate: a
// fan from a corner whose ring neighbours are corners, once corners beside edge points are cut
// off as ears (the best-shaped ear first). Without edge points, the fan from ring[0].
std::vector<std::array<int, 3>> triangulateRing(std::span<const Vec3> ring, std::vector<bool> corner);

}  // namespace radmesh
