// A scene's bounds, up axis and open side.
#include "viewer/scene_frame.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "solver/io/scene_loader.h"

namespace radmesh {
namespace {

// The unit box's faces seen from inside (normals point in), minus the ones named in `missing`.
std::vector<FrameFace> boxFromInside(std::vector<int> missing = {}) {
  std::vector<FrameFace> faces;
  for (int axis = 0; axis < 3; ++axis)
    for (int end = 0; end < 2; ++end) {
      if (std::find(missing.begin(), missing.end(), 2 * axis + end) != missing.end()) continue;
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      std::vector<Vec3> quad(4, Vec3(0.0));
      const double corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      for (int k = 0; k < 4; ++k) {
        quad[k][axis] = end;
        quad[k][u] = corners[k][0];
        quad[k][v] = corners[k][1];
      }
      // Counter-clockwise about +axis; the far side must face back in, -axis.
      if (end == 1) std::reverse(quad.begin(), quad.end());
      faces.push_back({quad});
    }
  return faces;
}

TEST(SceneFrame, BoundsEncloseEveryVertex) {
  const SceneFrame frame = frameOf(boxFromInside(), 2);
  EXPECT_EQ(frame.boundsMin, Vec3(0.0));
  EXPECT_EQ(frame.boundsMax, Vec3(1.0));
}

TEST(SceneFrame, FindsTheMissingWallAndNoneInAClosedBox) {
  EXPECT_EQ(frameOf(boxFromInside(), 1).openSide, -1);
  EXPECT_EQ(frameOf(boxFromInside({4}), 1).openSide, 4);  // z = 0 missing
  EXPECT_EQ(frameOf(boxFromInside({1}), 2).openSide, 1);  // x = 1 missing
}

TEST(SceneFrame, FloorAndCeilingNeverCountAsOpenSides) {
  EXPECT_EQ(frameOf(boxFromInside({5}), 2).openSide, -1);  // no ceiling: still no open wall
}

TEST(SceneFrame, TheBuiltInCornellBoxIsYUpAndOpenAtTheFront) {
  const SceneFrame frame = sceneFrame(loadScene("cornell"));
  EXPECT_EQ(frame.upAxis, 1);
  EXPECT_EQ(frame.openSide, 4);  // the classic camera looks in from z < 0
}

TEST(SceneFrame, TheBuiltInOfficeIsZUpAndClosed) {
  const SceneFrame frame = sceneFrame(loadScene("office"));
  EXPECT_EQ(frame.upAxis, 2);
  EXPECT_EQ(frame.openSide, -1);
}

}  // namespace
}  // namespace radmesh
