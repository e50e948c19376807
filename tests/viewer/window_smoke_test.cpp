// The window smoke test's check: tests/CMakeLists.txt runs `radmesh-view cornell --steps 5
// --screenshot FILE` under xvfb-run, then this test with RADMESH_SMOKE_SCREENSHOT=FILE. Run alone
// (without the variable), it skips.
#include <gtest/gtest.h>

#include <cstdlib>
#include <set>

#include "viewer/image.h"
#include "viewer/panel.h"

namespace radmesh {
namespace {

struct RegionStats {
  std::set<std::uint32_t> colours;
  double meanLevel = 0.0;
  long brightPixels = 0;  // any channel over 200: panel text and lit surfaces
};

RegionStats statsOf(const Image& image, int x0, int x1) {
  RegionStats s;
  double sum = 0.0;
  for (int y = 0; y < image.height; ++y)
    for (int x = x0; x < x1; ++x) {
      const std::uint8_t* p = &image.rgba[(size_t(y) * image.width + x) * 4];
      s.colours.insert(p[0] | p[1] << 8 | p[2] << 16);
      sum += (p[0] + p[1] + p[2]) / 3.0;
      if (p[0] > 200 || p[1] > 200 || p[2] > 200) ++s.brightPixels;
    }
  s.meanLevel = sum / (double(x1 - x0) * image.height);
  return s;
}

TEST(WindowSmoke, ScreenshotShowsTheLitSceneAndThePanel) {
  const char* path = std::getenv("RADMESH_SMOKE_SCREENSHOT");
  if (!path) GTEST_SKIP() << "RADMESH_SMOKE_SCREENSHOT is not set: ctest's viewer_window_smoke sets it";
  const Image shot = readPng(path);
  ASSERT_EQ(shot.width, 1280);
  ASSERT_EQ(shot.height, 720);
  const int panelX = shot.width - int(Panel::kWidthPx);
  const RegionStats scene = statsOf(shot, 0, panelX);
  const RegionStats panel = statsOf(shot, panelX, shot.width);
  // The lit Cornell box: many shades, not black.
  EXPECT_GT(scene.colours.size(), 200u);
  EXPECT_GT(scene.meanLevel, 30.0);
  // The panel: dark background with light text (hundreds of text pixels at least).
  EXPECT_LT(panel.meanLevel, 90.0);
  EXPECT_GT(panel.brightPixels, 500);
}

}  // namespace
}  // namespace radmesh
