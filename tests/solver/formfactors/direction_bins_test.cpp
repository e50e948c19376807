#include "solver/formfactors/direction_bins.h"

#include <gtest/gtest.h>

#include <map>
#include <vector>

#include "solver/formfactors/analytic_form_factor.h"
#include "solver/projection/single_plane.h"
#include "tests/solver/solver_test_helpers.h"

namespace radmesh {
namespace {

TEST(DirectionBins, AreTheHemicubesPixelsAndCoverTheHemisphere) {
  EXPECT_EQ(directionBinCount(0), 1);
  EXPECT_EQ(directionBinCount(1), 1);
  EXPECT_EQ(directionBinCount(2), 4 + 4 * 2);
  EXPECT_EQ(directionBinCount(3), 9 + 4 * 3 * 2);
  EXPECT_EQ(directionBinCount(4), 16 + 4 * 4 * 2);
  for (int n : {2, 3, 4, 8}) {
    double sum = 0.0;
    for (int b = 0; b < directionBinCount(n); ++b) sum += directionBinFormFactor(n, b);
    EXPECT_NEAR(sum, 1.0, 1e-12) << n;
  }
  // n = 2: each quarter of the top face is a unit square at height 1 with a corner over the patch.
  for (int b = 0; b < 4; ++b) EXPECT_NEAR(directionBinFormFactor(2, b), singlePlaneCapturedFraction(1.0) / 4, 1e-14);
  // n = 4: the top 0..15 (row by row from -v), then 8 bins each on the sides +u, -u, +v, -v.
  EXPECT_EQ(directionBin(4, {0.1, 0.1, 1.0}), 2 * 4 + 2);
  EXPECT_EQ(directionBin(4, {-0.9, -0.9, 1.0}), 0);
  EXPECT_EQ(directionBin(4, {0.9, 0.6, 1.0}), 3 * 4 + 3);
  EXPECT_EQ(directionBin(4, {1.0, 0.0, 0.1}), 16 + 2);       // +u side, a = v/u = 0, low row
  EXPECT_EQ(directionBin(4, {-1.0, -0.9, 0.8}), 24 + 4 + 0);  // -u side, a = -0.9, high row
  EXPECT_EQ(directionBin(4, {0.0, -1.0, 0.3}), 40 + 2);       // -v side
  EXPECT_EQ(directionBin(0, {0.0, -1.0, 0.3}), 0);
}

TEST(DirectionBins, SplitAPolygonExactly) {
  // The bin itself, at depth 2: all of it in the bin (n = 4: top face bin u, v in [0, 0.5]).
  const std::vector<Vec3> bin{{0, 0, 2}, {1, 0, 2}, {1, 1, 2}, {0, 1, 2}};
  std::map<int, double> parts;
  splitOverDirectionBins(4, bin, [&](int b, double f) { parts[b] += f; });
  EXPECT_NEAR(parts[10], directionBinFormFactor(4, 10), 1e-15);
  for (const auto& [b, f] : parts) {
    if (b != 10) {
      EXPECT_LT(f, 1e-15) << b;
    }
  }
  // A wall beside the patch, across the top and the +u side and partly below the horizon.
  const std::vector<Vec3> wall{{1, -0.7, -0.5}, {1, 0.9, -0.5}, {1, 0.9, 2.5}, {1, -0.7, 2.5}};
  for (int n : {1, 2, 3, 4, 8}) {
    double sum = 0.0;
    int count = 0;
    splitOverDirectionBins(n, wall, [&](int, double f) { sum += f, ++count; });
    EXPECT_NEAR(sum, pointToPolygonFormFactor(wall), 1e-13) << n;
    EXPECT_GT(count, n <= 1 ? 0 : n) << n;
  }
}

// A directional shooter's row split by bin adds up, per receiver, to its row entry, and its bins'
// totals to what the projection catches; other shooters' rows carry no bins.
TEST(DirectionBins, NativeRowsSplitByBinAddUpToTheRow) {
  const test::TestScene t = test::closedBox({1.0, 1.0, 1.0}, 4, {test::grey(0.5)});
  const int shooter = 5, other = 6;  // floor patches
  for (Projection projection : {Projection::Plane, Projection::Hemicube, Projection::Analytic}) {
    SolveOptions o = test::optionsFor(projection, 64);
    NativeBackend backend(t.scene, t.patches, o);
    backend.binDirections(std::vector<int>{shooter}, 8);
    std::vector<FormFactorRow> rows;
    backend.computeRows(std::vector<int>{shooter, other}, rows);
    const FormFactorRow& row = rows[0];
    EXPECT_TRUE(rows[1].binShares.empty());
    ASSERT_EQ(row.binTotals.size(), 192u);
    double totals = 0.0;
    int uncovered = 0;
    for (double f : row.binTotals) totals += f, uncovered += f == 0.0;
    EXPECT_NEAR(totals, row.capturedFraction, 1e-12);
    // The plane (ratio 3) sees down to 1/3 of the height over a distance: not the sides' lowest bins.
    EXPECT_EQ(uncovered, projection == Projection::Plane ? 4 * 8 : 0);
    std::map<int, double> perPatch;
    for (const FormFactorRow::BinShare& share : row.binShares) perPatch[share.patch] += share.formFactor;
    ASSERT_EQ(perPatch.size(), row.receivers.size());
    for (size_t r = 0; r < row.receivers.size(); ++r)
      EXPECT_NEAR(perPatch[row.receivers[r]], row.formFactors[r], 1e-12) << static_cast<int>(projection);
  }
}

}  // namespace
}  // namespace radmesh
