// Ear clipping (solver/geometry/polygon_triangulate.h) of outlines that visit the same points many
// times, as a face listing its vertices over and over does.
#include "solver/geometry/polygon_triangulate.h"

#include <gtest/gtest.h>

#include <vector>

namespace radmesh {
namespace {

TEST(Triangulate, AnOutlineGoingRoundATriangle30000TimesGivesTheTriangle30000Times) {
  constexpr int kRounds = 30000;
  const std::vector<Vec2> triangle{{0, 0}, {2, 0}, {0, 1}};
  std::vector<Vec2> outline;
  for (int k = 0; k < kRounds; ++k) outline.insert(outline.end(), triangle.begin(), triangle.end());
  const auto triangles = triangulatePolygon(outline, 1e-12);
  ASSERT_EQ(triangles.size(), size_t{kRounds});
  // Each the triangle itself, counter-clockwise from one of its corners: twice its area is 2.
  for (const auto& t : triangles)
    ASSERT_EQ(cross2(outline[t[1]] - outline[t[0]], outline[t[2]] - outline[t[0]]), 2.0);
}

}  // namespace
}  // namespace radmesh
