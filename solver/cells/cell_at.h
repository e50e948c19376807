#pragma once
// Which cell a point (the walkthrough's eye) is in, from the meshed scene and its partition.
#include <vector>

#include "solver/cells/cell_partition.h"
#include "solver/meshing/patch.h"

namespace radmesh {

// The cell of the nearest patch straight below `point` (against the unit `up`): the floor, or a
// table, under the eye. kOutsideCell where no patch lies below, where the nearest shows its back
// (a ceiling seen from the roof), or where it faces no cell.
int cellBelow(const std::vector<Patch>& patches, const CellPartition& partition, const Vec3& point, const Vec3& up);

// The cell whose free space's bounds lie nearest `point` (0 inside them; ties to the lower
// index); kOutsideCell for a partition with no cells.
int nearestCell(const CellPartition& partition, const Vec3& point);

}  // namespace radmesh
