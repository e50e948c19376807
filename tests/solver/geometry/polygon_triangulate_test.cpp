// Ear clipping (solver/geometry/polygon_triangulate.h) of outlines that visit the same points many
// times, as a face listing its vertices over and over does, and of large concave outlines, whose
// ears ask only the corners near them.
#include "solver/geometry/polygon_triangulate.h"

#include <gtest/gtest.h>

#include <vector>

#include "tests/solver/geometry/star_outline.h"

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

// An ear that missed a corner near it would lie over that vertex, or leave the remainder without
// an ear.
TEST(Triangulate, AStarOf3000VerticesGivesTrianglesThatCoverItAndHoldNoOtherVertex) {
  const std::vector<Vec2> outline = starOutline(3000, 1.0, 0.92);
  const auto triangles = triangulatePolygon(outline, 1e-12 * extentOf(outline));
  ASSERT_EQ(triangles.size(), outline.size() - 2);
  double twiceArea = 0.0;
  for (const auto& t : triangles) {
    const Vec2 &a = outline[t[0]], &b = outline[t[1]], &c = outline[t[2]];
    ASSERT_GT(cross2(b - a, c - a), 0.0);
    twiceArea += cross2(b - a, c - a);
    for (int v = 0; v < static_cast<int>(outline.size()); ++v) {
      if (v == t[0] || v == t[1] || v == t[2]) continue;
      const Vec2& q = outline[v];
      const bool inside = sideOfLine(a, b, q) > 1e-12 && sideOfLine(b, c, q) > 1e-12 && sideOfLine(c, a, q) > 1e-12;
      ASSERT_FALSE(inside) << "vertex " << v << " inside triangle " << t[0] << " " << t[1] << " " << t[2];
    }
  }
  EXPECT_NEAR(0.5 * twiceArea, signedArea(outline), 1e-12);
}

}  // namespace
}  // namespace radmesh
