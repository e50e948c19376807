#include "solver/projection/plane_mapping.h"

#include <gtest/gtest.h>

#include "solver/scene/scene_error.h"

namespace radmesh {
namespace {

TEST(PlaneMapping, BlocksKeepNeighbouringPixelsTogether) {
  const AxisMapping a = AxisMapping::blocks(128, 64);
  for (int p = 0; p < 128; ++p) EXPECT_EQ(a.peOf(p), p / 2);
  EXPECT_EQ(a.maxPixelsPerPe(), 2);
  EXPECT_EQ(a.stepsToCover(3, 4), 0);    // pixel 3 alone: PE 1
  EXPECT_EQ(a.stepsToCover(3, 10), 3);   // PEs 1..4
  const AxisMapping sparse = AxisMapping::blocks(16, 64);  // fewer pixels than PEs: spread out
  EXPECT_EQ(sparse.peOf(1), 4);
  EXPECT_EQ(sparse.pixelsOf(5).size(), 0u);
}

TEST(PlaneMapping, CutAndStackPutsNeighbouringPixelsOnNeighbouringPes) {
  const AxisMapping a = AxisMapping::cyclic(256, 64);
  EXPECT_EQ(a.peOf(70), 6);
  ASSERT_EQ(a.pixelsOf(6).size(), 4u);
  EXPECT_EQ(a.pixelsOf(6)[1], 70);
  EXPECT_EQ(a.stepsToCover(62, 66), 3);     // PEs 62, 63, 0, 1 round the torus
  EXPECT_EQ(a.stepsToCover(0, 200), 63);    // every PE
}

TEST(PlaneMapping, AdaptiveIsMonotoneAndGivesBusyPixelsSmallerBlocks) {
  std::vector<double> load(256, 0.0);
  for (int p = 100; p < 120; ++p) load[p] = 50.0;  // a busy stretch
  const AxisMapping a = AxisMapping::fromLoads(load, 64);
  for (int p = 1; p < 256; ++p) EXPECT_LE(a.peOf(p - 1), a.peOf(p));
  EXPECT_EQ(a.peOf(0), 0);
  EXPECT_EQ(a.peOf(255), 63);
  EXPECT_LE(a.pixelsOf(a.peOf(110)).size(), 1u);  // the busy stretch gets a PE per pixel
  // The floor keeps idle stretches from piling onto one PE: at most (1 + 1/floor) x average.
  EXPECT_LE(a.maxPixelsPerPe(), static_cast<int>(256 / 64 * (1.0 + 1.0 / kAdaptiveLoadFloor)));
}

TEST(PlaneMapping, ParsesItsNamesAndRefusesOthers) {
  EXPECT_EQ(parseMapping("cut-and-stack"), MappingKind::CutAndStack);
  EXPECT_EQ(parseMapping(toString(MappingKind::Adaptive)), MappingKind::Adaptive);
  EXPECT_THROW(parseMapping("diagonal"), OptionError);
}

}  // namespace
}  // namespace radmesh
