#include "viewer/exposure.h"

#include <gtest/gtest.h>

#include "solver/io/mgf_color.h"

namespace radmesh {
namespace {

TEST(Exposure, MapsThe95thPercentileToNearWhite) {
  // 100 greys of luminance 1..100 (grey g has luminance g): the 95th percentile (index 94 of
  // 0..99) is 95.
  std::vector<Rgb> b;
  for (int i = 100; i >= 1; --i) b.push_back(Rgb{double(i)});
  ASSERT_NEAR(luminance(Rgb{1.0}), 1.0, 1e-12);
  EXPECT_NEAR(autoExposure(b), 0.9 / 95.0, 1e-12);
}

TEST(Exposure, FallsBackToTheBrightestWhileMostIsDark) {
  std::vector<Rgb> b(100, Rgb{0.0});
  b[7] = Rgb{0, 0, 10.0};
  ASSERT_GT(luminance(b[7]), 0.0);
  EXPECT_DOUBLE_EQ(autoExposure(b), 0.9 / luminance(b[7]));
}

TEST(Exposure, IsOneWhenNothingIsLit) {
  EXPECT_DOUBLE_EQ(autoExposure({}), 1.0);
  EXPECT_DOUBLE_EQ(autoExposure(std::vector<Rgb>(5, Rgb{0.0})), 1.0);
}

}  // namespace
}  // namespace radmesh
