#pragma once
// Finding a building's cells and portals from its geometry alone (docs/cells.md says how).
#include <vector>

#include "solver/cells/cell_partition.h"
#include "solver/meshing/patch.h"
#include "solver/scene/scene.h"

namespace radmesh {

// The rooms of `scene` and the openings that join them; `patches` (meshScene's) are each given
// the cell they face. A scene that is one room gives one cell and no portals.
CellPartition findCells(const Scene& scene, const std::vector<Patch>& patches);

}  // namespace radmesh
