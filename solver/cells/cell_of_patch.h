#pragma once
// Which cell each patch faces (docs/cells.md, How, step 5). Internal to solver/cells/.
#include <vector>

#include "solver/cells/cell_partition.h"
#include "solver/cells/cell_portals.h"
#include "solver/cells/voxel_grid.h"
#include "solver/meshing/patch.h"

namespace radmesh {

// Each patch's cell: the voxel ahead of it, or the side it faces of a portal near it; else that of
// the nearest patch of its own polygon whose voxel ahead was free; else the nearest cell voxel
// within `reach` voxels; kOutsideCell for a face towards the outside.
std::vector<int> cellsFaced(const VoxelGrid& g, const VoxelLabels& labels, const ScenePolygons& polys,
                            const std::vector<Portal>& portals, const std::vector<Patch>& patches, int reach);

}  // namespace radmesh
