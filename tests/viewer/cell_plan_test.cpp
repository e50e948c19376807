#include "viewer/cell_plan.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "solver/cells/find_cells.h"
#include "solver/io/builtin_scenes.h"
#include "solver/meshing/meshing.h"
#include "solver/scene/up_axis.h"

namespace radmesh {
namespace {

std::map<std::array<std::uint8_t, 3>, long> colourCounts(const Image& image) {
  std::map<std::array<std::uint8_t, 3>, long> out;
  for (size_t i = 0; i < image.rgba.size(); i += 4) ++out[{image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]}];
  return out;
}

// two-rooms from above: the first room's floor in cell 0's colour west of the wall (x < 4), the
// second's in cell 1's east of it, a portal bar between, and the plan of the documented size.
TEST(CellPlan, TwoRoomsDrawsEachRoomInItsColourAndThePortal) {
  const Scene scene = builtinScene("two-rooms");
  const std::vector<Patch> patches = meshScene(scene);
  const CellPartition cells = findCells(scene, patches);
  ASSERT_EQ(cells.cells.size(), 2u);
  const Image plan = drawCellPlan(patches, cells, scene.upAxis);
  // 8.2 m x 4 m: the long side 1000 px, the short 1000 * 4 / 8.2 = 488 px, 20 px margins.
  EXPECT_EQ(cellPlanSize({0, 0, 0}, {8.2, 4, 2.7}), std::make_pair(1040, 528));
  EXPECT_EQ(plan.width, 1040);
  EXPECT_EQ(plan.height, 528);
  const auto counts = colourCounts(plan);
  const int first = cells.cells[0].name == "first" ? 0 : 1;
  // Each floor is 4 m x 4 m: about 488 x 488 px, less the walls' lines.
  EXPECT_GT(counts.at(cellPlanColour(first)), 400L * 400);
  EXPECT_GT(counts.at(cellPlanColour(1 - first)), 400L * 400);
  EXPECT_GT(counts.at({255, 0, 200}), 100) << "the portal's bar";
  auto pixel = [&](double x, double y) {  // metres -> the pixel's colour
    const int px = 20 + int(x * 1000 / 8.2), py = plan.height - 20 - int(y * 1000 / 8.2);
    const std::uint8_t* p = &plan.rgba[(size_t(py) * plan.width + px) * 4];
    return std::array<std::uint8_t, 3>{p[0], p[1], p[2]};
  };
  EXPECT_EQ(pixel(1.0, 1.0), cellPlanColour(first));
  EXPECT_EQ(pixel(7.0, 1.0), cellPlanColour(1 - first));
  EXPECT_NE(cellPlanColour(0), cellPlanColour(1));
}

// The same rooms stood on y, as office3 stands: the plan is drawn down y, the same picture (it used
// to be drawn down z whatever the up axis: office3's plan was a side view, 8.2 m by 2.7 m here).
TEST(CellPlan, AScenesUpAxisIsThePlansUp) {
  const Scene zUp = builtinScene("two-rooms");
  Scene yUp = zUp;
  for (Polygon& polygon : yUp.polygons)
    for (Vec3& v : polygon.vertices) v = rotateToYUp(v, 2);
  yUp.upAxis = 1;
  auto plan = [](const Scene& scene) {
    const std::vector<Patch> patches = meshScene(scene);
    return drawCellPlan(patches, findCells(scene, patches), scene.upAxis);
  };
  const Image fromZ = plan(zUp), fromY = plan(yUp);
  EXPECT_EQ(fromY.width, 1040);
  EXPECT_EQ(fromY.height, 528);
  long differ = 0;
  for (size_t i = 0; i < fromZ.rgba.size() && i < fromY.rgba.size(); ++i) differ += fromZ.rgba[i] != fromY.rgba[i];
  // Only the cell numbers may move, by a few pixels: a cell's bounds come from voxels laid along the
  // scene's own axes. The floors, walls and portal are the same pixels.
  EXPECT_LT(differ, 1000);
}

}  // namespace
}  // namespace radmesh
