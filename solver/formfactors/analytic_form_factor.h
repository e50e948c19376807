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

}  // namespace radmesh
