#pragma once
// A floor plan of a scene's cells (`radmesh info SCENE --plan FILE.png`): the view down the up
// axis (the scene's: office3 stands on y), each cell's floor and furniture tops in its own colour
// and its number at its middle, the walls cut at 1 m above the lowest floor drawn dark, and each
// portal a bright bar outlined dark.
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "solver/cells/cell_partition.h"
#include "solver/geometry/polygon_2d.h"
#include "solver/meshing/patch.h"
#include "viewer/image.h"

namespace radmesh {

inline constexpr int kPlanLongSidePx = 1000;  // the plan's longer side, margins aside
inline constexpr int kPlanMarginPx = 20;

// The plan's size for a scene whose patches span lo..hi: the longer horizontal side kPlanLongSidePx,
// the other in proportion, plus kPlanMarginPx on every side.
std::pair<int, int> cellPlanSize(const Vec3& lo, const Vec3& hi);

// The colour a cell is drawn in (RGB); distinct for neighbouring indices. kOutsideCell is grey.
std::array<std::uint8_t, 3> cellPlanColour(int cell);

// Seen from above the scene's `upAxis` (0 x, 1 y, 2 z), north (its UpFrame's along) up the page.
Image drawCellPlan(const std::vector<Patch>& patches, const CellPartition& cells, int upAxis);

}  // namespace radmesh
