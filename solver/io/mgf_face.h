#pragma once
// MGF faces as the planar polygons the scene needs. A face is kept as given (concave, or reaching
// holes through seams: the mesher handles both) after dropping zero-length edges; only a face
// that is visibly not flat is split into triangles.
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

// A face whose vertices lie farther than this fraction of its size from its Newell plane is split.
// Stricter than validateScene's planarity test, so every polygon returned passes it.
inline constexpr double kMgfFlatnessTolerance = 1e-4;

// Removes vertices equal (within 1e-12 of the polygon's size) to the one before them, the last
// compared with the first: zero-length edges from MGF seams, poles and apexes.
void dropRepeatedVertices(std::vector<Vec3>& vertices);

// The face itself when it is flat, else its triangles (ear-clipped in its Newell plane, each
// using the face's own vertices and its orientation), however far it is bent, as MGF's reference
// parser does. Throws MgfError for a face that cannot be built: fewer than three distinct
// vertices, no area, or a bent face folded or crossing itself. Sets *split when it split.
std::vector<std::vector<Vec3>> planarFace(std::vector<Vec3> face, bool* split);

}  // namespace radmesh
