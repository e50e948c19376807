#pragma once
// Visibility cells (the paper's section 1.7): a building's free space split into rooms that see
// little of each other, joined by portals (doors, windows between rooms). A shot in a cell projects
// only that cell's patches and its portals; light crosses to a neighbour only through a portal.
#include <string>
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

// What a patch belongs to when it faces no cell: the outside of an exterior wall, a roof's top.
inline constexpr int kOutsideCell = -1;

struct Cell {
  std::string name;  // "cell 3", or the group name the file gave the room
  Vec3 boundsMin{0.0};  // of the cell's free space, metres
  Vec3 boundsMax{0.0};
};

// An opening where two cells meet: a planar convex polygon that closes the opening, so that light
// leaving cellA for cellB crosses it, and nothing else joins the two.
struct Portal {
  std::vector<Vec3> vertices;  // counter-clockwise seen from cellA: the normal points into cellB
  int cellA = 0;
  int cellB = 0;
  double areaM2 = 0.0;
};

struct CellPartition {
  std::vector<Cell> cells;
  std::vector<Portal> portals;
  std::vector<int> cellOfPatch;  // per patch of the meshed scene: its cell, or kOutsideCell
};

}  // namespace radmesh
