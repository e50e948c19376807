#include "solver/bake/t_vertices.h"

#include <gtest/gtest.h>

#include <vector>

#include "solver/bake/display_radiosity.h"

namespace radmesh {
namespace {

Patch square(double x0, double y0, double side) {
  Patch p;
  p.vertices = {Vec3{x0, y0, 0}, Vec3{x0 + side, y0, 0}, Vec3{x0 + side, y0 + side, 0}, Vec3{x0, y0 + side, 0}};
  p.vertexCount = 4;
  p.normal = {0, 0, 1};
  p.areaM2 = side * side;
  p.centroid = {x0 + side / 2, y0 + side / 2, 0};
  return p;
}

double area(const DisplayMesh& mesh, size_t triangle) {
  const Vec3 a = mesh.positions[mesh.indices[3 * triangle]], b = mesh.positions[mesh.indices[3 * triangle + 1]],
             c = mesh.positions[mesh.indices[3 * triangle + 2]];
  return 0.5 * glm::dot(glm::cross(b - a, c - a), Vec3{0, 0, 1});  // signed: > 0 counter-clockwise
}

int vertexAt(const DisplayMesh& mesh, const Vec3& p) {
  for (size_t v = 0; v < mesh.positions.size(); ++v)
    if (mesh.positions[v] == p) return static_cast<int>(v);
  return -1;
}

// A 2 m quad beside two 1 m quads: the corner they share, (2, 1), lies inside the big quad's edge.
TEST(TVertices, TheBigQuadsTrianglesTakeInTheTVertexAndCoverItExactly) {
  const std::vector<Patch> patches{square(0, 0, 2), square(2, 0, 1), square(2, 1, 1)};
  const DisplayMesh mesh = buildDisplayMesh(patches);
  EXPECT_EQ(mesh.positions.size(), 8u);  // 4 + 6 corners, two of them shared: no vertex added
  const int t = vertexAt(mesh, {2, 1, 0});
  ASSERT_GE(t, 0);
  double bigArea = 0.0;
  int bigTriangles = 0;
  bool usesT = false;
  for (size_t i = 0; i < mesh.patchOfTriangle.size(); ++i) {
    EXPECT_GE(area(mesh, i), 0.5) << "triangle " << i << " is degenerate or turned";
    if (mesh.patchOfTriangle[i] != 0) continue;
    ++bigTriangles;
    bigArea += area(mesh, i);
    for (int k = 0; k < 3; ++k) usesT = usesT || mesh.indices[3 * i + k] == static_cast<unsigned>(t);
  }
  EXPECT_EQ(bigTriangles, 3);  // the fan from (0, 0) over (2, 0), (2, 1), (2, 2), (0, 2)
  EXPECT_EQ(bigArea, 4.0);
  EXPECT_TRUE(usesT);
  EXPECT_EQ(mesh.patchOfTriangle.size(), 7u);

  // Gouraud across the edge: the T-vertex takes the mean of the edge's ends, (4 * 1 + 1 * 3) / 5
  // and (4 * 1 + 1 * 5) / 5, not the mean of the small quads beside it (4).
  const std::vector<Rgb> b = vertexRadiosity(mesh, {Rgb(1.0), Rgb(3.0), Rgb(5.0)});
  EXPECT_NEAR(b[vertexAt(mesh, {2, 0, 0})].r, 1.4, 1e-12);
  EXPECT_NEAR(b[vertexAt(mesh, {2, 2, 0})].r, 1.8, 1e-12);
  EXPECT_NEAR(b[t].r, 1.6, 1e-12);
}

// Points on every edge of a triangle: no corner can be the fan's apex until ears are cut off.
TEST(TVertices, ATriangleWithPointsOnEveryEdgeTriangulatesWithoutDegenerateTriangles) {
  const std::vector<Vec3> ring{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1.5, 1, 0}, {1, 2, 0}, {0.5, 1, 0}};
  const std::vector<bool> corner{true, false, true, false, true, false};
  const auto triangles = triangulateRing(ring, corner);
  ASSERT_EQ(triangles.size(), 4u);  // n - 2
  double sum = 0.0;
  for (const auto& t : triangles) {
    const double a = 0.5 * glm::cross(ring[t[1]] - ring[t[0]], ring[t[2]] - ring[t[0]]).z;
    EXPECT_GE(a, 0.25);
    sum += a;
  }
  EXPECT_DOUBLE_EQ(sum, 2.0);
}

// Points within the tolerance of an edge count, its ends and points off it do not; coincident
// points count once.
TEST(TVertices, FindEdgePointsKeepsPointsInsideEdgesOnce) {
  const std::vector<Vec3> square{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  const std::vector<std::span<const Vec3>> outlines{square};
  const std::vector<Vec3> points{{1, 1e-12, 0}, {2, 0, 0}, {1, 0.01, 0}, {2, 1.5, 0}, {1, 0, 0}, {0, 0.5, 0}};
  const auto found = findEdgePoints(outlines, points, 1e-9);
  ASSERT_EQ(found.size(), 1u);
  ASSERT_EQ(found[0].size(), 3u);
  EXPECT_EQ(found[0][0].edge, 0);
  EXPECT_EQ(found[0][0].point, 0);
  EXPECT_DOUBLE_EQ(found[0][0].t, 0.5);
  EXPECT_EQ(found[0][1].edge, 1);
  EXPECT_EQ(found[0][1].point, 3);
  EXPECT_DOUBLE_EQ(found[0][1].t, 0.75);
  EXPECT_EQ(found[0][2].edge, 3);
  EXPECT_EQ(found[0][2].point, 5);
  EXPECT_DOUBLE_EQ(found[0][2].t, 0.75);
}

}  // namespace
}  // namespace radmesh
