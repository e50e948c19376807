#pragma once
// The portals of findCells (docs/cells.md): each place two cells' voxels touch, turned into the
// exact rectangle of the opening there from the scene's polygons. Internal to solver/cells/.
#include <utility>
#include <vector>

#include "solver/cells/cell_partition.h"
#include "solver/cells/voxel_grid.h"

namespace radmesh {

// The scene's polygons with their bounds.
struct ScenePolygons {
  const Scene& scene;
  std::vector<std::pair<Vec3, Vec3>> bounds;
  explicit ScenePolygons(const Scene& s);
};

// One portal per opening between two cells, in the order of the cells' pairs; `radius` is the
// erosion's, in voxels (how far from where the cells meet the opening's planes may lie).
std::vector<Portal> findPortals(const VoxelGrid& g, const VoxelLabels& labels, const ScenePolygons& polys, int radius);

}  // namespace radmesh
