#pragma once
// Point-to-polygon form factor by Lambert's contour integral (as used by Baum et al. 1989):
// exact, without occlusion, so exact for convex enclosures; the oracle for the projections.
#include <span>

#include "solver/scene/scene.h"

namespace radmesh {

// Form factor from a differential area at the origin facing +z (a shooter's centroid in its own
// frame) to the convex polygon `vertices`, the part behind the differential area (z < 0) clipped
// away. Either winding gives the same, non-negative value.
double pointToPolygonFormFactor(std::span<const Vec3> vertices);

// The same for a small polygon far away: where every corner is in front (z > 0) and the polygon's
// diameter is at most kSmallPolygonRatio of its centroid's distance, the differential form
// cos(at the origin) cos(at the polygon) area / (pi r^2) that the exact one tends to (within 0.3 %
// there, tests/solver/formfactors); else pointToPolygonFormFactor. An atan2 per edge is most of what
// sharing a patch's form factor among its elements costs otherwise.
inline constexpr double kSmallPolygonRatio = 0.1;
double smallPolygonFormFactor(std::span<const Vec3> vertices, Vec3 centroid, Vec3 normal, double areaM2);
// The largest squared distance between two of the vertices.
double squaredDiameter(std::span<const Vec3> vertices);
// That differential form alone, for a polygon known to pass smallPolygonFormFactor's test.
double differentialFormFactor(Vec3 centroid, Vec3 normal, double areaM2);

// Area to area, from the planar polygon `from` to the planar polygon `to`, each wholly in front of
// the other and apart (no occlusion): Stokes' double contour integral,
// A_from F = 1/(2 pi) |sum over edge pairs of the integral of ln r dp.dq|, exact however narrow
// the gap, where sampling points of either polygon fails once the gap is under their spacing
// (1 m plates 1 cm apart, 8 cuts: 1.5 % high). Either winding of either gives the same.
// Costs a few thousand logarithms: for the pairs sampling cannot serve.
double polygonToPolygonFormFactor(std::span<const Vec3> from, std::span<const Vec3> to);

}  // namespace radmesh
