#pragma once
// Finding a building's cells and portals from its geometry alone (docs/cells.md says how).
#include <string>
#include <vector>

#include "solver/cells/cell_partition.h"
#include "solver/meshing/patch.h"
#include "solver/scene/scene.h"

namespace radmesh {

// The rooms of `scene` and the openings that join them; `patches` (meshScene's) are each given
// the cell they face. A scene that is one room gives one cell and no portals.
CellPartition findCells(const Scene& scene, const std::vector<Patch>& patches);

// What the groups a file names (groupOfOrigin) do to the cells found from the geometry.
enum class CellGroups {
  Name,  // they name the cells, nothing more (findCells's default)
  Join,  // cells whose patch area is mostly in the same group are also one cell, and the portals
         // between them dropped: a room the geometry split (around a pillar, by tall shelving)
         // that the file names as one
};
CellPartition findCells(const Scene& scene, const std::vector<Patch>& patches, CellGroups groups);

// The named group a polygon's origin puts it in, "" if none: a built-in room ("room 'NAME' wall
// -x"), an MGF object ("line 7: f (object 'NAME/part')"). A cell takes the name of the group that
// holds most of its patch area.
std::string groupOfOrigin(const std::string& origin);

}  // namespace radmesh
