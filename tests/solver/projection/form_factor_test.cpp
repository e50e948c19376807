// Form factors by environment projection (single plane, hemicube) against closed forms and the
// analytic oracle, with the error shrinking as the resolution grows.
#include <gtest/gtest.h>

#include <vector>

#include "solver/projection/single_plane.h"
#include "tests/solver/closed_forms.h"
#include "tests/solver/solver_test_helpers.h"

namespace radmesh {
namespace {

using test::addGrid;
using test::areaFormFactor;
using test::optionsFor;
using test::range;
using test::TestScene;

constexpr int kQuadrature = 8;  // the shooter is cut into 8 x 8 points

TestScene squares(bool perpendicular) {
  TestScene t;
  t.scene.source = perpendicular ? "perpendicular squares" : "parallel squares";
  t.scene.materials = {test::grey(0.5, 1.0)};
  addGrid(t.patches, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, kQuadrature, kQuadrature);
  if (perpendicular)
    addGrid(t.patches, {0, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1, 1);
  else
    addGrid(t.patches, {0, 0, 1}, {0, 1, 0}, {1, 0, 0}, 1, 1);
  return t;
}

// |projected - oracle| at each resolution, the oracle being the analytic form factor with the
// same quadrature points (so only the projection's own error is measured).
std::vector<double> errors(const TestScene& t, Projection projection, double ratio,
                           const std::vector<int>& resolutions, double& oracle) {
  const auto shooters = range(0, kQuadrature * kQuadrature);
  const std::vector<int> receiver{kQuadrature * kQuadrature};
  oracle = areaFormFactor(t, optionsFor(Projection::Analytic), shooters, receiver);
  std::vector<double> e;
  for (int n : resolutions) {
    SolveOptions o = optionsFor(projection, n);
    o.ratio = ratio;
    e.push_back(std::abs(areaFormFactor(t, o, shooters, receiver) - oracle));
  }
  return e;
}

void expectShrinking(const std::vector<double>& e, double boundAtHighest) {
  for (size_t k = 1; k < e.size(); ++k) EXPECT_LT(e[k], e[k - 1]) << "resolution step " << k;
  EXPECT_LT(e.back(), boundAtHighest);
}

TEST(ProjectedFormFactor, ParallelUnitSquaresOneApart) {
  double oracle = 0.0;
  const TestScene t = squares(false);
  expectShrinking(errors(t, Projection::Plane, 3.0, {16, 64, 256}, oracle), 1e-3);
  EXPECT_NEAR(oracle, test::parallelRectanglesFormFactor(1, 1, 1), 1e-3);  // 0.1998
  expectShrinking(errors(t, Projection::Hemicube, 3.0, {16, 64, 256}, oracle), 1e-3);
}

TEST(ProjectedFormFactor, PerpendicularUnitSquaresSharingAnEdge) {
  double oracle = 0.0;
  const TestScene t = squares(true);
  expectShrinking(errors(t, Projection::Hemicube, 3.0, {16, 64, 256}, oracle), 1e-3);
  EXPECT_NEAR(oracle, test::perpendicularRectanglesFormFactor(1, 1, 1), 2e-3);  // 0.2000
  // The single plane misses what lies beyond its edge: near the hinge the wall is at grazing angles.
  SolveOptions plane = optionsFor(Projection::Plane, 256);
  const double caught = areaFormFactor(t, plane, range(0, kQuadrature * kQuadrature), {kQuadrature * kQuadrature});
  EXPECT_LT(caught, oracle - 0.01);
}

TEST(ProjectedFormFactor, DifferentialAreaUnderACentredSquareOfHalfSide3) {
  TestScene t;
  t.scene.source = "point under a square";
  t.scene.materials = {test::grey(0.5, 1.0)};
  addGrid(t.patches, {-5e-4, -5e-4, 0}, {1e-3, 0, 0}, {0, 1e-3, 0}, 1, 1);
  addGrid(t.patches, {-3, -3, 1}, {0, 6, 0}, {6, 0, 0}, 1, 1);
  const double exact = singlePlaneCapturedFraction(3.0);
  EXPECT_NEAR(exact, 0.9169, 1e-4);
  for (Projection p : {Projection::Hemicube, Projection::Plane}) {
    std::vector<double> e;
    for (int n : {16, 64, 256}) {
      SolveOptions o = optionsFor(p, n);
      o.ratio = 4.0;  // wider than the square, so its edge falls inside the plane
      e.push_back(std::abs(test::entry(test::rowsOf(t, o, {0})[0], 1) - exact));
    }
    expectShrinking(e, 2e-3);
  }
}

TEST(ProjectedFormFactor, ClosedBoxRowsCatchEveryPixelOnce) {
  // Every direction of the hemisphere meets a wall: the row sums to the whole table exactly when
  // no pixel is dropped or counted twice, and the hemicube's table sums to 1.
  const TestScene box = test::closedBox({1.0, 1.3, 0.9}, 4, {test::grey(0.5, 1.0)});
  const auto all = range(0, static_cast<int>(box.patches.size()));
  for (Projection p : {Projection::Hemicube, Projection::Plane}) {
    const SolveOptions o = optionsFor(p, 64);
    const double captured = p == Projection::Plane ? singlePlaneCapturedFraction(3.0) : 1.0;
    for (const FormFactorRow& row : test::rowsOf(box, o, all)) {
      EXPECT_NEAR(row.hitFraction(), captured, 1e-12) << toString(p) << " shooter " << row.shooter;
      EXPECT_EQ(row.capturedFraction, captured);
      EXPECT_EQ(row.escapedFraction(), 0.0);
      EXPECT_EQ(row.backFaces, 0.0);
    }
  }
}

TEST(ProjectedFormFactor, ReciprocityBetweenFacesOfABox) {
  // Face-to-face exchange A_P F_PQ = A_Q F_QP, each face's patches its quadrature points.
  const int d = 6;
  const TestScene box = test::closedBox({1.0, 1.3, 0.9}, d, {test::grey(0.5, 1.0)});
  auto face = [&](int f) { return range(f * d * d, (f + 1) * d * d); };
  const SolveOptions o = optionsFor(Projection::Hemicube, 128);
  const double floorArea = 1.0 * 1.3, wallArea = 1.3 * 0.9;  // floor (face 0), wall x = 0 (face 2)
  for (auto [p, q, areaP, areaQ] : {std::tuple{0, 1, floorArea, floorArea}, std::tuple{0, 2, floorArea, wallArea}}) {
    const double pq = areaP * areaFormFactor(box, o, face(p), face(q));
    const double qp = areaQ * areaFormFactor(box, o, face(q), face(p));
    EXPECT_NEAR(pq, qp, 0.02 * pq) << "faces " << p << ", " << q;
  }
}

TEST(ProjectedFormFactor, SinglePlaneItemBufferShowsEveryPixelInAClosedBox) {
  const TestScene box = test::closedBox({1.0, 1.3, 0.9}, 4, {test::grey(0.5, 1.0)});
  for (Projection p : {Projection::Plane, Projection::Hemicube, Projection::Analytic}) {
    NativeBackend backend(box.scene, box.patches, optionsFor(p, 32));
    const ItemBuffer buffer = backend.singlePlaneItemBuffer(5);
    EXPECT_EQ(buffer.width, 32);
    EXPECT_EQ(std::count(buffer.items.begin(), buffer.items.end(), ItemBuffer::kNone), 0);
    EXPECT_EQ(std::count(buffer.items.begin(), buffer.items.end(), 5), 0);  // not itself
    for (int id : buffer.items) EXPECT_NE(box.patches[id].polygon, 0) << "the shooter's own floor";
  }
}

}  // namespace
}  // namespace radmesh
