#include "solver/cells/cell_at.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

#include "solver/cells/find_cells.h"
#include "solver/io/builtin_scenes.h"
#include "solver/meshing/meshing.h"

namespace radmesh {
namespace {

// An eye 1.6 m above the middle of each room's and corridor's floor is in that room's cell; above
// the roof and below the ground floor it is in none.
TEST(CellAt, TheEyeAboveARoomsFloorIsInThatRoomsCell) {
  const Scene scene = builtinScene("building:2x2");
  const std::vector<Patch> patches = meshScene(scene);
  const CellPartition partition = findCells(scene, patches);
  std::map<std::string, int> cellByName;
  for (size_t c = 0; c < partition.cells.size(); ++c) cellByName[partition.cells[c].name] = int(c);
  const Vec3 up(0, 0, 1);
  int floors = 0;
  for (const Polygon& polygon : scene.polygons) {
    if (polygon.origin.find(" floor") == std::string::npos) continue;
    Vec3 middle(0.0);
    for (const Vec3& v : polygon.vertices) middle += v / double(polygon.vertices.size());
    const std::string room = groupOfOrigin(polygon.origin);
    EXPECT_EQ(cellBelow(patches, partition, middle + 1.6 * up, up), cellByName.at(room)) << room;
    EXPECT_EQ(cellBelow(patches, partition, middle - 0.5 * up, up), kOutsideCell) << "below " << room;
    ++floors;
  }
  EXPECT_EQ(floors, 4 + 2);  // the rooms, the wing's corridor and the spine
  const Vec3 centre = 0.5 * (partition.cells[0].boundsMin + partition.cells[0].boundsMax);
  EXPECT_EQ(cellBelow(patches, partition, centre + 100.0 * up, up), kOutsideCell) << "on the roof";
}

TEST(CellAt, NearestCellIsTheOneWhoseBoundsAreNearest) {
  CellPartition partition;
  EXPECT_EQ(nearestCell(partition, Vec3(0.0)), kOutsideCell);
  partition.cells = {{"a", Vec3(0.0), Vec3(1.0)}, {"b", Vec3(2.0, 0.0, 0.0), Vec3(3.0, 1.0, 1.0)}};
  EXPECT_EQ(nearestCell(partition, Vec3(0.5)), 0);
  EXPECT_EQ(nearestCell(partition, Vec3(1.4, 0.5, 0.5)), 0);
  EXPECT_EQ(nearestCell(partition, Vec3(1.6, 9.0, -4.0)), 1);
  EXPECT_EQ(nearestCell(partition, Vec3(1.5, 0.5, 0.5)), 0) << "a tie goes to the lower index";
}

}  // namespace
}  // namespace radmesh
