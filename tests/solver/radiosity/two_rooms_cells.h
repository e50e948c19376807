#pragma once
// two-rooms (solver/io/builtin_scenes.cpp) as cells, by hand: room A is x 0..4, the dividing wall
// x 4..4.2 with a door at y 1.55..2.45, z 0..2.1, room B x 4.2..8.2. The portal is the door in A's
// face of the wall (x = 4); the passage belongs to B.
#include <vector>

#include "solver/cells/cell_partition.h"
#include "solver/io/builtin_scenes.h"
#include "solver/meshing/meshing.h"
#include "solver/meshing/patch.h"

namespace radmesh::test {

constexpr double kWallFaceX = 4.0;

inline bool inRoomA(const Patch& p) { return p.centroid.x <= kWallFaceX + 1e-9; }

// Without the door, two cells that see nothing of each other.
inline CellPartition twoRoomsPartition(const std::vector<Patch>& patches, bool withDoor = true) {
  CellPartition partition;
  partition.cells = {{"A", {0, 0, 0}, {4, 4, 2.7}}, {"B", {4, 0, 0}, {8.2, 4, 2.7}}};
  if (withDoor)
    partition.portals = {{{{4, 1.55, 0}, {4, 2.45, 0}, {4, 2.45, 2.1}, {4, 1.55, 2.1}}, 0, 1, 0.9 * 2.1}};
  for (const Patch& p : patches) partition.cellOfPatch.push_back(inRoomA(p) ? 0 : 1);
  return partition;
}

// The scene and its patches at the paper's cell size.
struct TwoRooms {
  Scene scene = builtinScene("two-rooms");
  std::vector<Patch> patches = meshScene(scene);
};

// Area-weighted mean reflected radiosity (B - E, summed over RGB) of one room's receivers
// (patches or elements, `b` theirs).
inline double reflectedInRoom(const Scene& scene, const std::vector<Patch>& receivers, const std::vector<Rgb>& b,
                              bool roomA) {
  double weighted = 0.0, area = 0.0;
  for (size_t j = 0; j < receivers.size(); ++j) {
    if (inRoomA(receivers[j]) != roomA) continue;
    const Rgb e = scene.materials[receivers[j].material].emittance;
    weighted += (b[j].r + b[j].g + b[j].b - e.r - e.g - e.b) * receivers[j].areaM2;
    area += receivers[j].areaM2;
  }
  return weighted / area;
}

}  // namespace radmesh::test
