#pragma once
// Which cells of a building the eye may see, so that the renderer draws those alone (a building
// of a hundred rooms is too many triangles a frame for a software GL). Portal culling: the cells
// whose free space holds the eye are seen whole; from each seen cell, a portal within the part of
// the screen it is seen through shows the cell beyond, through the screen rectangle of the
// portal, narrowed at every portal on the way.
#include <glm/mat4x4.hpp>

#include <vector>

#include "solver/cells/cell_partition.h"

namespace radmesh {

// Per cell of the partition: whether it may be seen. Empty when the eye is in no cell (outside
// the building, where anything may be seen). Conservative: a cell seen is never left out.
std::vector<bool> visibleCells(const CellPartition& partition, const glm::mat4& viewProjection, const Vec3& eye);

}  // namespace radmesh
