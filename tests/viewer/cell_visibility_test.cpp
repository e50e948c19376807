// Portal culling: from a room, the room beyond a door is seen only through the door.
#include "viewer/cell_visibility.h"

#include <gtest/gtest.h>

#include "solver/cells/find_cells.h"
#include "solver/io/scene_loader.h"
#include "solver/meshing/meshing.h"
#include "viewer/render_view.h"

namespace radmesh {
namespace {

struct TwoRooms {
  CellPartition partition;
  Vec3 doorMiddle{0.0};
  Vec3 roomMiddle(int cell) const {
    return 0.5 * (partition.cells[cell].boundsMin + partition.cells[cell].boundsMax);
  }
};

TwoRooms twoRooms() {
  const Scene scene = loadScene("two-rooms");
  TwoRooms t{findCells(scene, meshScene(scene, 0.381))};
  for (const Vec3& v : t.partition.portals.at(0).vertices) t.doorMiddle += v / double(t.partition.portals[0].vertices.size());
  return t;
}

glm::mat4 looking(const Vec3& eye, const Vec3& at) {
  RenderView view;
  view.eye = eye;
  view.look = at;
  view.up = Vec3(0, 0, 1);
  return viewProjectionMatrix(view, 16.0 / 9.0);
}

TEST(CellVisibility, TheRoomBeyondTheDoorIsSeenOnlyThroughIt) {
  const TwoRooms t = twoRooms();
  ASSERT_EQ(t.partition.cells.size(), 2u);
  ASSERT_EQ(t.partition.portals.size(), 1u);
  Vec3 eye = t.roomMiddle(0);
  eye.z = t.doorMiddle.z;  // level with the door's middle
  EXPECT_EQ(visibleCells(t.partition, looking(eye, t.doorMiddle), eye), (std::vector<bool>{true, true}))
      << "facing the door";
  EXPECT_EQ(visibleCells(t.partition, looking(eye, 2.0 * eye - t.doorMiddle), eye), (std::vector<bool>{true, false}))
      << "the door behind";
  // Facing along the door's wall, the door lies outside the view's sides.
  const Vec3 alongWall = glm::cross(Vec3(0, 0, 1), glm::normalize(t.doorMiddle - eye));
  const Vec3 nearWall = t.doorMiddle + 0.3 * (eye - t.doorMiddle) / glm::length(eye - t.doorMiddle) - 1.5 * alongWall;
  EXPECT_EQ(visibleCells(t.partition, looking(nearWall, nearWall - alongWall), nearWall),
            (std::vector<bool>{true, false}))
      << "the door beside";
}

TEST(CellVisibility, OutsideEveryRoomEverythingMayBeSeen) {
  const TwoRooms t = twoRooms();
  const Vec3 far = t.partition.cells[0].boundsMax + Vec3(50.0, 50.0, 0.0);
  EXPECT_TRUE(visibleCells(t.partition, looking(far, t.roomMiddle(0)), far).empty());
}

}  // namespace
}  // namespace radmesh
