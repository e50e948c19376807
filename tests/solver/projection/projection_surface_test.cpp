#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <utility>

#include "solver/projection/hemicube.h"
#include "solver/projection/single_plane.h"
#include "solver/scene/scene_error.h"

namespace radmesh {
namespace {

double sum(const ProjectionSurface& s) {
  double total = 0.0;
  for (const auto& table : s.deltaFormFactors)
    for (double df : table) total += df;
  return total;
}

TEST(SinglePlane, CapturedFractionClosedForm) {
  EXPECT_NEAR(singlePlaneCapturedFraction(3.0), 0.91688173, 1e-8);  // the paper's 91.7 %
  EXPECT_NEAR(singlePlaneCapturedFraction(1e6), 1.0, 1e-6);      // an infinite plane: everything
  EXPECT_NEAR(singlePlaneCapturedFraction(1e-3), 4.0 / std::numbers::pi * 1e-6, 1e-11);  // small: area / pi
  EXPECT_DOUBLE_EQ(singlePlaneCapturedFraction(1e155), 1.0);  // r^2 would overflow: still everything
}

// Pixels as wide as the plane's height miss the peak under the shooter: the table sums to far less
// than the closed form, and scaling it up would put the light in the wrong places. Refused.
TEST(SinglePlane, PixelsTooCoarseToSampleTheFormFactorAreRefused) {
  EXPECT_NO_THROW(makeSinglePlane(64, 20.0));  // pixels 0.625 wide: 0.07 % off
  EXPECT_NO_THROW(makeSinglePlane(16, 3.0));   // the coarsest the CLI allows at the paper's ratio
  // 1e308: the table's pixels overflow and it sums to NaN, which passed a plain comparison.
  for (const auto& [n, ratio] : {std::pair{64, 50.0}, std::pair{16, 10.0}, std::pair{256, 1000.0}, std::pair{128, 1e308}}) {
    try {
      makeSinglePlane(n, ratio);
      ADD_FAILURE() << "N " << n << ", ratio " << ratio << " was accepted";
    } catch (const OptionError& e) {
      EXPECT_NE(std::string(e.what()).find("too coarse to sample the form factor"), std::string::npos) << e.what();
    }
  }
}

// A plane so small it catches under 1 % of a shot loses nearly all the light (--ratio 1e-9 caught
// 1e-18 of it and solved on, booking all as lost). Refused; 0.1, catching 1.26 %, is not.
TEST(SinglePlane, APlaneThatCatchesNearlyNothingIsRefused) {
  EXPECT_NEAR(makeSinglePlane(32, 0.1).capturedFraction, 0.012565, 1e-6);
  for (const double ratio : {0.08, 1e-3, 1e-9}) {
    try {
      makeSinglePlane(32, ratio);
      ADD_FAILURE() << "ratio " << ratio << " was accepted";
    } catch (const OptionError& e) {
      EXPECT_NE(std::string(e.what()).find("so the solve would lose nearly all its light; give --ratio 0.1 or more"),
                std::string::npos)
          << e.what();
    }
  }
}

TEST(SinglePlane, TableSumConvergesToTheClosedFormAsResolutionGrows) {
  const double exact = singlePlaneCapturedFraction(3.0);
  double previous = 1.0;
  for (int n : {16, 64, 256, 1024}) {
    const ProjectionSurface plane = makeSinglePlane(n, 3.0);
    const double error = std::abs(plane.tableSum - exact);
    EXPECT_LT(error, previous / 8.0) << "N = " << n;  // midpoint rule: error ~ 1/N^2
    previous = error;
    EXPECT_NEAR(sum(plane), exact, 1e-12);  // the table used is scaled to the closed form
    EXPECT_DOUBLE_EQ(plane.capturedFraction, exact);
  }
  EXPECT_LT(previous, 1e-6);
}

TEST(SinglePlane, PixelsCarryTheDeltaFormFactorOfTheirCentre) {
  const ProjectionSurface plane = makeSinglePlane(16, 2.0);
  const ProjectionFace& face = plane.faces[0];
  const double scale = plane.capturedFraction / plane.tableSum;
  const double dA = 0.25 * 0.25;
  // Pixel (0, 0) is centred at (-1.875, -1.875).
  EXPECT_NEAR(plane.deltaFormFactors[0][0] / scale, dA / (std::numbers::pi * std::pow(2 * 1.875 * 1.875 + 1, 2)), 1e-15);
  EXPECT_DOUBLE_EQ(face.pixelCentre(0, 0).x, -1.875);
  EXPECT_EQ(plane.deltaFormFactors[0][0], plane.deltaFormFactors[0][15 * 16 + 15]);  // symmetric
}

TEST(Hemicube, FacesTileTheHemisphereAndTheTableSumsToOne) {
  double previous = 1.0;
  for (int n : {16, 64, 256}) {
    const ProjectionSurface cube = makeHemicube(n);
    ASSERT_EQ(cube.faces.size(), 5u);
    EXPECT_EQ(cube.faces[0].width * cube.faces[0].height, n * n);
    for (int f = 1; f < 5; ++f) EXPECT_EQ(cube.faces[f].height, n / 2);
    const double error = std::abs(cube.tableSum - 1.0);
    EXPECT_LT(error, previous / 8.0) << "N = " << n;
    previous = error;
    EXPECT_NEAR(sum(cube), 1.0, 1e-12);
    EXPECT_EQ(cube.capturedFraction, 1.0);
  }
  EXPECT_LT(previous, 1e-5);
}

TEST(Hemicube, SideFacesCarryCosineWeightedDeltaFormFactors) {
  EXPECT_DOUBLE_EQ(hemicubeSideDeltaFormFactor(0.0, 0.0, 1.0), 0.0);  // the horizon emits nothing
  EXPECT_NEAR(hemicubeSideDeltaFormFactor(0.0, 1.0, 1.0), 1.0 / (4.0 * std::numbers::pi), 1e-15);
  // The top face's corner and the side face's top corner are the same direction: equal per solid angle.
  EXPECT_NEAR(singlePlaneDeltaFormFactor(1.0, 1.0, 1.0), hemicubeSideDeltaFormFactor(1.0, 1.0, 1.0), 1e-15);
}

// A cells solve's hundred back ends project onto one surface: made once while any holds it.
TEST(SharedSurface, IsMadeOnceWhileHeldAndAgainWhenLetGo) {
  int made = 0;
  auto make = [&] {
    ++made;
    return makeHemicube(16);
  };
  std::shared_ptr<const ProjectionSurface> first = sharedSurface("test hemicube 16", make);
  const std::shared_ptr<const ProjectionSurface> second = sharedSurface("test hemicube 16", make);
  EXPECT_EQ(made, 1);
  EXPECT_EQ(first.get(), second.get());
  EXPECT_EQ(first->deltaFormFactors, makeHemicube(16).deltaFormFactors);
  const std::shared_ptr<const ProjectionSurface> other = sharedSurface("test hemicube 16 again", make);
  EXPECT_EQ(made, 2);
  EXPECT_NE(other.get(), first.get());
  const ProjectionSurface* was = first.get();
  first.reset();
  EXPECT_EQ(sharedSurface("test hemicube 16", make).get(), was);  // `second` still holds it
  EXPECT_EQ(made, 2);
}

}  // namespace
}  // namespace radmesh
