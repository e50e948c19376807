#include "solver/geometry/coplanar_merge.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "solver/meshing/meshing.h"

namespace radmesh {
namespace {

Polygon tri(Vec3 a, Vec3 b, Vec3 c, int material = 0, std::string origin = "t") {
  return Polygon{{a, b, c}, material, std::move(origin)};
}

// Same cycle of vertices, whatever the starting vertex.
bool sameCycle(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  if (a.size() != b.size()) return false;
  for (size_t shift = 0; shift < a.size(); ++shift) {
    bool all = true;
    for (size_t i = 0; i < a.size() && all; ++i) all = a[(i + shift) % a.size()] == b[i];
    if (all) return true;
  }
  return false;
}

const std::vector<Vec3> kQuad = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};

TEST(CoplanarMerge, QuadGivenAsTwoTrianglesBecomesTheQuadItself) {
  MergeReport report;
  const auto out = mergeCoplanarTriangles({tri(kQuad[0], kQuad[1], kQuad[2], 3, "mesh 'q' primitive 0"),
                                           tri(kQuad[0], kQuad[2], kQuad[3], 3, "mesh 'q' primitive 0")},
                                          &report);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].vertices, kQuad);  // vertex for vertex, in order
  EXPECT_EQ(out[0].material, 3);
  EXPECT_EQ(out[0].origin, "mesh 'q' primitive 0");
  EXPECT_EQ(report.trianglesIn, 2u);
  EXPECT_EQ(report.polygonsOut, 1u);

  // The other diagonal gives the same quad (from another start vertex).
  const auto other = mergeCoplanarTriangles({tri(kQuad[1], kQuad[2], kQuad[3]), tri(kQuad[1], kQuad[3], kQuad[0])});
  ASSERT_EQ(other.size(), 1u);
  EXPECT_TRUE(sameCycle(other[0].vertices, kQuad));
}

TEST(CoplanarMerge, MergedQuadMeshesExactlyLikeTheQuad) {
  Scene quad{"quad", {{"lamp", Rgb(0.5), Rgb(1.0)}}, {{kQuad, 0, "quad"}}, {}};
  Scene split = quad;
  split.polygons = mergeCoplanarTriangles({tri(kQuad[0], kQuad[1], kQuad[2]), tri(kQuad[0], kQuad[2], kQuad[3])});
  const auto a = meshScene(quad, 0.381), b = meshScene(split, 0.381);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a.size(), 2u);  // the grid does cut this 2 m x 1 m quad
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].vertexCount, b[i].vertexCount);
    EXPECT_EQ(a[i].vertices, b[i].vertices);
    EXPECT_EQ(a[i].areaM2, b[i].areaM2);
  }
}

TEST(CoplanarMerge, LShapeOfFourTrianglesIsOneSixVertexPolygon) {
  const Vec3 o{0, 0, 0}, a{2, 0, 0}, b{2, 1, 0}, c{1, 1, 0}, d{1, 2, 0}, e{0, 2, 0};
  const auto out = mergeCoplanarTriangles({tri(o, a, b), tri(o, b, c), tri(o, c, d), tri(o, d, e)});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(sameCycle(out[0].vertices, {o, a, b, c, d, e}));
  EXPECT_DOUBLE_EQ(polygonArea(out[0].vertices), 3.0);
  EXPECT_GT(newellNormal(out[0].vertices).z, 0.0);  // still counter-clockwise seen from +z
}

TEST(CoplanarMerge, DifferentMaterialsDoNotMerge) {
  const auto out = mergeCoplanarTriangles({tri(kQuad[0], kQuad[1], kQuad[2], 0), tri(kQuad[0], kQuad[2], kQuad[3], 1)});
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].vertices.size(), 3u);
  EXPECT_EQ(out[1].material, 1);
}

TEST(CoplanarMerge, FoldedPairsDoNotMerge) {
  // A right-angle crease, and a fold of only 1 mrad (the far corner 1 mm out of plane).
  for (double rise : {1.0, 1e-3}) {
    const auto out = mergeCoplanarTriangles({tri({0, 0, 0}, {1, 0, 0}, {1, 1, 0}), tri({0, 0, 0}, {1, 1, 0}, {0, 1, rise})});
    EXPECT_EQ(out.size(), 2u) << "rise " << rise;
  }
}

TEST(CoplanarMerge, OppositeFacingCoplanarTrianglesDoNotMerge) {
  // The second triangle shares the edge in the same direction, so it faces -z.
  const auto out = mergeCoplanarTriangles({tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), tri({1, 0, 0}, {0, 1, 0}, {1, 1, 0})});
  EXPECT_EQ(out.size(), 2u);
}

TEST(CoplanarMerge, NearlyEqualCornersAreWelded) {
  const Vec3 nudge{1e-12, -1e-12, 0};
  const auto out = mergeCoplanarTriangles({tri(kQuad[0], kQuad[1], kQuad[2]), tri(kQuad[0] + nudge, kQuad[2] - nudge, kQuad[3])});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].vertices, kQuad);
}

// One stray triangle 1e7 m away must not stretch the weld over the model: the two unit squares,
// 0.01 m apart, stay two squares and keep their corners.
TEST(CoplanarMerge, AStrayFarTriangleDoesNotWeldTheModelTogether) {
  const Vec3 gap{2.01, 0, 0};
  std::vector<Polygon> input{tri(kQuad[0], kQuad[1], kQuad[2]), tri(kQuad[0], kQuad[2], kQuad[3]),
                             tri(kQuad[0] + gap, kQuad[1] + gap, kQuad[2] + gap),
                             tri(kQuad[0] + gap, kQuad[2] + gap, kQuad[3] + gap)};
  input.push_back(tri({1e7, 0, 0}, {1e7 + 1, 0, 0}, {1e7, 1, 0}));
  MergeReport report;
  const auto out = mergeCoplanarTriangles(input, &report);
  EXPECT_EQ(report.degenerateDropped, 0u);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[0].vertices, kQuad);
  EXPECT_NEAR(totalArea(out), 2.0 + 2.0 + 0.5, 1e-9);
}

TEST(CoplanarMerge, VertexInTheMiddleOfAnEdgeIsRemoved) {
  const Vec3 a{0, 0, 0}, m{1, 0, 0}, b{2, 0, 0}, c{2, 1, 0}, d{0, 1, 0};
  const auto out = mergeCoplanarTriangles({tri(a, m, d), tri(m, b, c), tri(m, c, d)});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(sameCycle(out[0].vertices, {a, b, c, d}));
}

TEST(CoplanarMerge, RingAroundAHoleBecomesSimplePolygonsOfTheSameArea) {
  // A 4 x 4 square with a 2 x 2 hole, as 8 triangles (the ceiling around a light, say).
  const Vec3 o0{0, 0, 0}, o1{4, 0, 0}, o2{4, 4, 0}, o3{0, 4, 0};
  const Vec3 i0{1, 1, 0}, i1{3, 1, 0}, i2{3, 3, 0}, i3{1, 3, 0};
  const std::vector<Polygon> ring = {tri(o0, o1, i1), tri(o0, i1, i0), tri(o1, o2, i2), tri(o1, i2, i1),
                                     tri(o2, o3, i3), tri(o2, i3, i2), tri(o3, o0, i0), tri(o3, i0, i3)};
  const auto out = mergeCoplanarTriangles(ring);
  ASSERT_GE(out.size(), 2u);  // one polygon cannot have a hole
  ASSERT_LT(out.size(), ring.size());
  double area = 0.0;
  for (const Polygon& p : out) {
    area += polygonArea(p.vertices);
    EXPECT_GT(newellNormal(p.vertices).z, 0.0);
    // Simple: no vertex repeats (a polygon around a hole would visit a cut vertex twice).
    for (size_t i = 0; i < p.vertices.size(); ++i)
      for (size_t j = i + 1; j < p.vertices.size(); ++j) EXPECT_NE(p.vertices[i], p.vertices[j]);
  }
  EXPECT_DOUBLE_EQ(area, 12.0);
}

TEST(CoplanarMerge, DegenerateTrianglesAreDroppedAndOthersPassThrough) {
  MergeReport report;
  const Polygon pentagon{{{0, 0, 5}, {2, 0, 5}, {3, 1, 5}, {1, 2, 5}, {-1, 1, 5}}, 0, "pentagon"};
  const auto out = mergeCoplanarTriangles(
      {tri({0, 0, 0}, {1, 0, 0}, {1, 0, 0}), tri({0, 0, 0}, {1, 0, 0}, {2, 0, 0}), pentagon, tri({0, 0, 1}, {1, 0, 1}, {0, 1, 1})},
      &report);
  EXPECT_EQ(report.degenerateDropped, 2u);  // a repeated corner; three collinear corners
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].vertices, pentagon.vertices);
  EXPECT_EQ(out[1].vertices.size(), 3u);
}

}  // namespace
}  // namespace radmesh
