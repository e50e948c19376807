#pragma once
// The bake (`radmesh solve --out FILE.glb`): the meshed geometry with its display radiosity as
// per-vertex colour, as a glTF 2.0 binary that any glTF viewer shows.
#include <string>
#include <vector>

#include "solver/bake/display_radiosity.h"

namespace radmesh {

// How radiosity becomes a displayable colour: COLOR_0 = min(1, B / radiosityPerColorUnit) per
// channel, with radiosityPerColorUnit (W/m^2) the 90th percentile over vertices of their largest
// channel. Like a camera's exposure: the walls show, and the brightest tenth (the lights, mostly)
// saturate. Falls back to the maximum when that percentile is 0, and to 1 when everything is 0.
double bakeRadiosityPerColorUnit(const std::vector<Rgb>& vertexRadiosity);

// Writes POSITION, NORMAL, COLOR_0 (linear float RGB, as above), 32-bit indices and one material
// with KHR_materials_unlit, so viewers show COLOR_0 as it is. The mesh is turned from its scene's
// up axis onto glTF's +y (rotateToYUp, solver/scene/up_axis.h), so that glTF viewers show it
// upright and radmesh's start view is kept. The mesh's extras hold "radiosityPerColorUnit"
// (W/m^2) so that B can be recovered, and "sourceUp", the scene's up axis ("x", "y" or "z"). A
// model farther from the origin than 8 times its size is written about its centre, the node
// translated by it (in double), so that its float positions keep their precision.
// Throws std::invalid_argument for radiosity that does not match the mesh or is negative or not
// finite (never written), and OptionError naming the path when the file cannot be written.
void writeBakeGlb(const std::string& path, const DisplayMesh& mesh, const std::vector<Rgb>& vertexRadiosity,
                  int sceneUpAxis);

}  // namespace radmesh
