#include "solver/projection/scan_conversion.h"

#include "solver/projection/single_plane.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace radmesh {
namespace {

constexpr int kSize = 32;

ScreenPolygon screen(std::vector<glm::dvec2> vertices, double inverseDepthC = 1.0,
                     double inverseDepthX = 0.0, double inverseDepthY = 0.0) {
  ScreenPolygon s;
  s.vertexCount = static_cast<int>(vertices.size());
  std::copy(vertices.begin(), vertices.end(), s.vertices.begin());
  s.inverseDepthX = inverseDepthX;
  s.inverseDepthY = inverseDepthY;
  s.inverseDepthC = inverseDepthC;
  return s;
}

PolygonSetup setUp(const ScreenPolygon& s, int id = 0) {
  PolygonSetup setup;
  EXPECT_TRUE(setupPolygon(s, kSize, kSize, id, id, setup));
  return setup;
}

// How many of the polygons cover each pixel, by the per-pixel test.
std::vector<int> coverageCounts(const std::vector<PolygonSetup>& setups) {
  std::vector<int> counts(kSize * kSize, 0);
  for (const PolygonSetup& s : setups)
    for (int row = 0; row < kSize; ++row)
      for (int column = 0; column < kSize; ++column) counts[row * kSize + column] += covers(s, column, row);
  return counts;
}

TEST(ScanConversion, TwoTrianglesSharingADiagonalCoverEachPixelOnce) {
  // Every vertex on a pixel centre and the diagonal through a row of them: all ties.
  const glm::dvec2 a{2.5, 2.5}, b{10.5, 2.5}, c{10.5, 10.5}, d{2.5, 10.5};
  for (bool reversed : {false, true}) {
    std::vector<PolygonSetup> setups{setUp(screen({a, b, c}), 0),
                                     setUp(reversed ? screen({d, c, a}) : screen({a, c, d}), 1)};
    const std::vector<int> counts = coverageCounts(setups);
    int covered = 0;
    for (int row = 0; row < kSize; ++row)
      for (int column = 0; column < kSize; ++column) {
        const int n = counts[row * kSize + column];
        EXPECT_LE(n, 1) << "pixel " << column << "," << row << " counted twice";
        const bool strictlyInside = column > 2 && column < 10 && row > 2 && row < 10;
        if (strictlyInside) {
          EXPECT_EQ(n, 1) << "pixel " << column << "," << row << " dropped";
        }
        covered += n;
      }
    // The half-open square: one of each pair of opposite sides owns its centres, 8 x 8 in all.
    EXPECT_EQ(covered, 64);
  }
}

TEST(ScanConversion, FanAroundAPixelCentreCoversEachPixelOnce) {
  const glm::dvec2 centre{16.5, 16.5};
  const std::vector<glm::dvec2> ring{{10.5, 10.5}, {16.5, 9.5},  {22.5, 10.5}, {23.5, 16.5},
                                     {22.5, 22.5}, {16.5, 23.5}, {10.5, 22.5}, {9.5, 16.5}};
  std::vector<PolygonSetup> fan;
  for (size_t k = 0; k < ring.size(); ++k)
    fan.push_back(setUp(screen({centre, ring[k], ring[(k + 1) % ring.size()]}), static_cast<int>(k)));
  const std::vector<int> counts = coverageCounts(fan);
  EXPECT_EQ(counts[16 * kSize + 16], 1) << "the shared vertex's pixel";
  for (int n : counts) EXPECT_LE(n, 1);
  for (int row = 12; row <= 20; ++row)
    for (int column = 12; column <= 20; ++column) EXPECT_EQ(counts[row * kSize + column], 1);
}

// A random triangulated rectangle: jittered grid vertices, half of them snapped to pixel centres.
TEST(ScanConversion, RandomTriangulationCoversEachPixelOnce) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-1.4, 1.4);
  constexpr int kGrid = 6;
  const double step = 5.0;
  glm::dvec2 grid[kGrid + 1][kGrid + 1];
  for (int i = 0; i <= kGrid; ++i)
    for (int j = 0; j <= kGrid; ++j) {
      glm::dvec2 p{1.0 + i * step, 1.0 + j * step};
      if (i > 0 && i < kGrid && j > 0 && j < kGrid) p += glm::dvec2(jitter(random), jitter(random));
      if ((i + j) % 2 == 0) p = glm::floor(p) + 0.5;
      grid[i][j] = p;
    }
  std::vector<PolygonSetup> setups;
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      const glm::dvec2 p00 = grid[i][j], p10 = grid[i + 1][j], p11 = grid[i + 1][j + 1], p01 = grid[i][j + 1];
      const int id = static_cast<int>(setups.size());
      setups.push_back(setUp(screen({p00, p10, p11}), id));
      setups.push_back(setUp(screen({p00, p11, p01}), id + 1));
    }
  const std::vector<int> counts = coverageCounts(setups);
  for (int row = 0; row < kSize; ++row)
    for (int column = 0; column < kSize; ++column) {
      const int n = counts[row * kSize + column];
      EXPECT_LE(n, 1) << column << "," << row;
      if (column >= 3 && column < 29 && row >= 3 && row < 29) {
        EXPECT_EQ(n, 1) << "pixel " << column << "," << row << " dropped";
      }
    }
}

// The span rasteriser and the per-pixel test (which the mesh back end uses) must agree exactly:
// coverage and every bit of the depth.
TEST(ScanConversion, SpansAgreeWithPerPixelTestOnRandomPolygons) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(-6.0, kSize + 6.0);
  std::uniform_real_distribution<double> slope(-0.05, 0.05);
  std::uniform_int_distribution<int> snap(0, 2);
  std::uniform_real_distribution<double> huge(-1e9, 1e9);
  int compared = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const int n = 3 + trial % 2;
    std::vector<glm::dvec2> v(n);
    for (auto& p : v) {
      p = {coordinate(random), coordinate(random)};
      if (snap(random) == 0) p = glm::floor(p) + 0.5;  // ties on pixel centres
    }
    if (trial % 5 == 0) v[0] = {huge(random), huge(random)};   // clipped near the shooter: far out
    if (trial % 7 == 0) v[1].y = v[0].y + 1e-7;               // an edge nearly along a row
    if (n == 4) {  // make the quad convex: sort around its centre
      const glm::dvec2 c = (v[0] + v[1] + v[2] + v[3]) / 4.0;
      std::sort(v.begin(), v.end(), [&](glm::dvec2 a, glm::dvec2 b) {
        return std::atan2(a.y - c.y, a.x - c.x) < std::atan2(b.y - c.y, b.x - c.x);
      });
    }
    PolygonSetup setup;
    if (!setupPolygon(screen(v, 2.0, slope(random), slope(random)), kSize, kSize, 0, 0, setup)) continue;
    ItemBuffer buffer(kSize, kSize);
    const std::vector<int> ranks{0};
    rasterise(setup, buffer, 0, kSize, ranks);
    for (int row = 0; row < kSize; ++row)
      for (int column = 0; column < kSize; ++column) {
        const bool pixel = covers(setup, column, row);
        ASSERT_EQ(buffer.item(column, row) == 0, pixel) << "trial " << trial << " pixel " << column << "," << row;
        if (pixel) {
          ASSERT_EQ(buffer.inverseDepth[buffer.index(column, row)], inverseDepthAt(setup, column, row));
        }
        compared += pixel;
      }
  }
  EXPECT_GT(compared, 10000);  // the trials really drew something
}

TEST(ScanConversion, BandsOfRowsGiveTheSameBufferAsOnePass) {
  const PolygonSetup setup = setUp(screen({{3.2, 1.1}, {29.7, 12.4}, {14.1, 30.9}}, 1.0, 0.01, 0.02));
  ItemBuffer whole(kSize, kSize), banded(kSize, kSize);
  const std::vector<int> ranks{0};
  rasterise(setup, whole, 0, kSize, ranks);
  for (int row = 0; row < kSize; row += 5) rasterise(setup, banded, row, std::min(kSize, row + 5), ranks);
  EXPECT_EQ(whole.items, banded.items);
  EXPECT_EQ(whole.inverseDepth, banded.inverseDepth);
}

TEST(ScanConversion, NearerPatchWinsAndCoplanarTiesGoToTheLowerRankInEitherOrder) {
  EXPECT_TRUE(closer(0.5, 9, 0.4, 0));   // nearer (larger 1/depth) wins whatever the ranks
  EXPECT_FALSE(closer(0.4, 0, 0.5, 9));
  EXPECT_TRUE(closer(0.5, 1, 0.5 * (1 + 1e-9), 2));  // a tie: rank decides
  EXPECT_FALSE(closer(0.5 * (1 + 1e-9), 2, 0.5, 1));

  // Two coplanar overlapping squares whose depths differ by rounding only.
  const ScreenPolygon a = screen({{2, 2}, {20, 2}, {20, 20}, {2, 20}}, 0.5);
  const ScreenPolygon b = screen({{10, 10}, {28, 10}, {28, 28}, {10, 28}}, 0.5 * (1 + 1e-12));
  PolygonSetup sa, sb;
  ASSERT_TRUE(setupPolygon(a, kSize, kSize, 0, 1, sa));  // patch 0 has rank 1
  ASSERT_TRUE(setupPolygon(b, kSize, kSize, 1, 0, sb));  // patch 1 has rank 0
  const std::vector<int> rankOf{1, 0};
  ItemBuffer first(kSize, kSize), second(kSize, kSize);
  rasterise(sa, first, 0, kSize, rankOf);
  rasterise(sb, first, 0, kSize, rankOf);
  rasterise(sb, second, 0, kSize, rankOf);
  rasterise(sa, second, 0, kSize, rankOf);
  EXPECT_EQ(first.items, second.items);
  EXPECT_EQ(first.item(15, 15), 1);  // the overlap goes to rank 0
}

TEST(ScanConversion, PolygonsOutsideTheFaceOrWithoutAreaAreRefused) {
  PolygonSetup setup;
  EXPECT_FALSE(setupPolygon(screen({{40, 40}, {50, 40}, {45, 50}}), kSize, kSize, 0, 0, setup));
  EXPECT_FALSE(setupPolygon(screen({{1, 1}, {5, 5}, {9, 9}}), kSize, kSize, 0, 0, setup));
  EXPECT_FALSE(setupPolygon(screen({{-9, -9}, {-1, -9}, {-5, -1}}), kSize, kSize, 0, 0, setup));
}

// projectOntoFace refuses, before projecting, a polygon wholly more than two pixels beyond an edge
// of the face's window (setupPolygon could set up no pixel of it), even one reaching behind the
// eye; one that crosses the window, or lies within a pixel of it, is projected as before.
TEST(ProjectOntoFace, APolygonWhollyBeyondTheWindowIsRefusedBeforeProjection) {
  const ProjectionSurface plane = makeSinglePlane(16, 2.0);  // a, b in [-2, 2] at depth 1: 0.25 a pixel
  const ProjectionFace& face = plane.faces[0];
  auto square = [](double x0, double x1, double z0, double z1) {
    LocalPolygon p;
    p.vertexCount = 4;
    p.vertices = {Vec3(x0, -0.5, z0), Vec3(x1, -0.5, z1), Vec3(x1, 0.5, z1), Vec3(x0, 0.5, z0)};
    p.normal = glm::normalize(glm::cross(p.vertices[1] - p.vertices[0], p.vertices[2] - p.vertices[1]));
    p.centroid = 0.25 * (p.vertices[0] + p.vertices[1] + p.vertices[2] + p.vertices[3]);
    p.planeOffset = glm::dot(p.normal, p.centroid);
    return p;
  };
  ScreenPolygon out;
  PolygonSetup setup;
  EXPECT_FALSE(projectOntoFace(square(2.6, 3.0, 1.0, 1.0), face, 1e-9, out));     // 2.4 pixels past a = 2
  EXPECT_FALSE(projectOntoFace(square(-3.0, -2.6, 1.0, 1.0), face, 1e-9, out));   // and past a = -2
  EXPECT_FALSE(projectOntoFace(square(0.5, 3.0, -1.0, 1.0), face, 1e-9, out));    // from behind the eye
  EXPECT_TRUE(projectOntoFace(square(1.5, 3.0, 1.0, 1.0), face, 1e-9, out));      // across the edge
  EXPECT_TRUE(setupPolygon(out, face.width, face.height, 0, 0, setup));
  EXPECT_TRUE(covers(setup, 15, 8));
  EXPECT_TRUE(projectOntoFace(square(2.1, 3.0, 1.0, 1.0), face, 1e-9, out));      // 0.4 pixels past it
}

}  // namespace
}  // namespace radmesh
