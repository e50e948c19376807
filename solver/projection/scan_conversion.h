#pragma once
// Scan conversion and z-buffering into the item buffer (the paper's section 1.5, scan-conversion
// phase). Two ways to the same pixels: covers()/inverseDepthAt() decide one pixel at a time (the
// mesh back end z-buffers pixel by pixel on its PEs), rasterise() fills spans for speed, and both
// give bit-identical coverage and depth.
#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include "solver/projection/item_buffer.h"
#include "solver/meshing/patch.h"
#include "solver/projection/projection.h"

namespace radmesh {

// One edge of a projected polygon, stored from the lexicographically smaller endpoint so that the
// two polygons sharing an edge evaluate exactly the same number, one of them negated.
struct EdgeFunction {
  double startX = 0.0, startY = 0.0;
  double dirX = 0.0, dirY = 0.0;  // end - start, negated where needed so that the inside is > 0
  bool ownsTies = false;          // top-left rule: a pixel centre exactly on the edge belongs here
  // For span filling: the edge's column per row (startX + (y - startY) * inverseSlope), and how far
  // a pixel centre must be from that column for rounding not to matter.
  double inverseSlope = 0.0;
  double crossingSlack = 0.0;
};

// Everything a pixel needs to know about one projected patch: set up once per patch and shot.
struct PolygonSetup {
  int id = -1;    // patch index, written into the item buffer
  int rank = 0;   // depth-tie order (see depthTieRanks)
  int edgeCount = 0;
  std::array<EdgeFunction, ScreenPolygon::kMaxVertices> edges;  // the first edgeCount are set
  double inverseDepthX = 0.0, inverseDepthY = 0.0, inverseDepthC = 0.0;
  int columnBegin = 0, columnEnd = 0;  // pixels [columnBegin, columnEnd) x [rowBegin, rowEnd)
  int rowBegin = 0, rowEnd = 0;        // hold every pixel centre the polygon may cover
  double areaPixels = 0.0;             // projected area, in pixels
  double widthPixels = 0.0;            // area over the longest edge: a sliver's narrow width, in pixels
  double depthTieTolerance = 0.0;     // for closer(): kDepthTieTolerance, or kBeamDepthTieTolerance
};

// False when the polygon has no area or lies wholly outside the width x height face.
bool setupPolygon(const ScreenPolygon& polygon, int width, int height, int id, int rank,
                  PolygonSetup& setup);

// The rest of the projection phase for one patch in view (inShooterView) and one face, in both
// back ends: projectOntoFace, then setupPolygon. False when it leaves no pixel on the face.
bool setUpProjection(const LocalPolygon& patch, const ProjectionFace& face, double nearDepth, int id, int rank,
                     PolygonSetup& setup);

// Is the centre of pixel (column, row) inside? Top-left fill rule: a centre on an edge shared by
// two polygons belongs to exactly one of them.
bool covers(const PolygonSetup& setup, int column, int row);
// True perspective 1/depth of the polygon's plane at the centre of pixel (column, row).
double inverseDepthAt(const PolygonSetup& setup, int column, int row);

// z-compare: is A in front of B? Depths equal to a relative tolerance (coplanar patches) are
// ordered by rank, so the winner does not depend on the order patches are drawn in.
// A light's parallel beam ties only what rounding cannot tell apart: depth along it is affine and
// exact to a few ulps, while 1e-6 would tie the pixels within 1e-4 of one of a closed room's
// corners, where the room's inside, when its rank is lower, let the sun in through the seam.
inline constexpr double kDepthTieTolerance = 1e-6;
inline constexpr double kBeamDepthTieTolerance = 1e-12;
inline bool closer(double inverseDepthA, int rankA, double inverseDepthB, int rankB,
                   double tolerance = kDepthTieTolerance) {
  const double difference = inverseDepthA - inverseDepthB;
  const double scale = std::max(std::abs(inverseDepthA), std::abs(inverseDepthB));
  if (std::abs(difference) <= tolerance * scale) return rankA < rankB;
  return difference > 0.0;  // the larger 1/depth is the nearer
}

// Depth-tie ranks: each patch's position when sorted by geometry (centroid, area, material), so
// coplanar overlaps resolve the same way whatever order the scene lists its polygons in.
std::vector<int> depthTieRanks(const std::vector<Patch>& patches);
// A patch's depth-tie rank in one shot: its depthTieRanks rank, behind every patch seen from the
// front when the shooter sees its back. Two coincident patches facing opposite ways (a wall of no
// thickness between two rooms, each room's box with its own side of it) tie at every pixel; the
// shooter sees the one facing it, where the geometric rank alone gave both rooms the same one and
// the other stayed black.
inline int shotTieRank(int rank, bool seenFromFront, int patchCount) {
  return seenFromFront ? rank : rank + patchCount;
}

// The pixels [first, second) of `row` whose centres the polygon covers (empty: first == second),
// by the rule covers() applies pixel by pixel.
std::pair<int, int> rowSpan(const PolygonSetup& setup, int row);

// How many pixel centres the polygon covers: rowSpan over its rows.
long long coveredPixelCount(const PolygonSetup& setup);

// z-buffers the polygon into rows [rowBegin, rowEnd) of the buffer, span by span; rankOf gives
// the rank of a patch already in the buffer. Returns how many pixel centres it covers there.
long long rasterise(const PolygonSetup& setup, ItemBuffer& buffer, int rowBegin, int rowEnd,
               std::span<const int> rankOf);

}  // namespace radmesh
