#pragma once
// Slicing polygons into patches on a global grid (the paper's section 1.6).
#include <string>
#include <vector>

#include "solver/meshing/patch.h"
#include "solver/scene/scene.h"

namespace radmesh {

inline constexpr double kDefaultCellM = 0.381;  // 15 inches, the paper's grid
// Models whose smallest extent is below this are smaller than a room: their cell follows their size.
inline constexpr double kRoomSizedM = 1.5;
// The cell chosen for a model when none is given: at most about this many patches.
inline constexpr double kCellPatchBudget = 200'000;
// ... and for an object smaller than a room in every direction, about a room's (the office: 3932).
inline constexpr double kObjectPatchBudget = 4'000;

struct CellChoice {
  double cellM = kDefaultCellM;
  std::string why;  // one line for the user: what was chosen and from what
};

// The cell for a model when the user gives none: the paper's 15 inches for room-sized models and
// buildings; a sixteenth of the smallest extent for a model smaller than a room (a 0.55 m box
// would be 42 patches at 15 inches), coarser where an object that small would make more than
// about kObjectPatchBudget patches; and for a model so large that 15 inches would make more than
// about kCellPatchBudget patches, the cell of that many.
CellChoice chooseCell(const Scene& scene);
// --preset elements' patch cell from the scene's choice: elementsPresetCell of it, and why.
CellChoice elementsPresetChoice(const CellChoice& sceneCell);

// Throws OptionError naming --cell unless cellM is finite and positive.
void checkCell(double cellM);

// Every polygon is cut by the planes x = k*cell, y = k*cell, z = k*cell that cross its face (the
// two axes spanning its dominant plane) into convex pieces within one cell each, then into
// triangles and convex quads. The grid is the world's, or turned to follow a model or a wing
// drawn at an angle to the world axes (gridsOf, solver/meshing/grid_turn.h). Area, orientation and
// material are kept. Throws OptionError for a cell that is not finite and positive, or that would
// make more than `maxPatches` patches.
std::vector<Patch> meshScene(const Scene& scene, double cellM = kDefaultCellM,
                             size_t maxPatches = 2'000'000);

}  // namespace radmesh
