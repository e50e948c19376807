#include "viewer/frame_report.h"

#include <gtest/gtest.h>

namespace radmesh {
namespace {

// Taking in a snapshot takes some µs: the report said "longest 0.0 ms" of a nonzero time.
TEST(FrameReport, TimesUnderATenthOfAMillisecondAreInMicroseconds) {
  EXPECT_EQ(frameTimeText(0.0167), "16.7 ms");
  EXPECT_EQ(frameTimeText(1e-4), "0.1 ms");
  EXPECT_EQ(frameTimeText(4.2e-5), "42 µs");
  EXPECT_EQ(frameTimeText(3.25e-8), "0.0325 µs");
  EXPECT_EQ(frameTimeText(0.0), "0 µs");
  FrameReport report;
  EXPECT_EQ(report.summary(), "");
  report.add(0.02, 3e-6);
  report.add(0.05, 4.2e-5);
  EXPECT_EQ(report.summary(), "2 frames with the mesh: lowest 20.0 fps (50.0 ms), median 20.0 fps (50.0 ms), mean "
                              "28.6 fps, 1 under 30 fps; taking in snapshots: median 42 µs, longest 42 µs a frame");
}

}  // namespace
}  // namespace radmesh
