#include "solver/formfactors/analytic_form_factor.h"

#include <gtest/gtest.h>

#include <vector>

#include "solver/scene/scene_error.h"
#include "solver/projection/single_plane.h"
#include "tests/solver/closed_forms.h"
#include "tests/solver/solver_test_helpers.h"

namespace radmesh {
namespace {

using test::addGrid;
using test::areaFormFactor;
using test::range;
using test::TestScene;

double pointForm(std::vector<Vec3> v) { return pointToPolygonFormFactor(v); }

TEST(AnalyticFormFactor, DifferentialAreaUnderACentredSquareOfHalfSide3) {
  const std::vector<Vec3> square{{-3, -3, 1}, {3, -3, 1}, {3, 3, 1}, {-3, 3, 1}};
  EXPECT_NEAR(pointForm(square), 0.9169, 5e-5);
  EXPECT_NEAR(pointForm(square), singlePlaneCapturedFraction(3.0), 1e-14);
  EXPECT_NEAR(pointForm({square.rbegin(), square.rend()}), pointForm(square), 1e-15);  // winding
}

TEST(AnalyticFormFactor, ThePartBehindTheDifferentialAreaIsClippedAway) {
  EXPECT_EQ(pointForm({{-1, -1, -1}, {1, -1, -1}, {0, 1, -1}}), 0.0);
  // A wall straddling the horizon counts only its upper half.
  const double straddling = pointForm({{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}});
  const double upperHalf = pointForm({{1, -1, 0}, {1, 1, 0}, {1, 1, 1}, {1, -1, 1}});
  EXPECT_GT(upperHalf, 0.05);
  EXPECT_NEAR(straddling, upperHalf, 1e-15);
  // A polygon in the differential area's own plane receives nothing.
  EXPECT_NEAR(pointForm({{1, 1, 0}, {2, 1, 0}, {2, 2, 0}}), 0.0, 1e-15);
}

// Area to area: the shooter cut into m x m quadrature points.
TestScene parallelSquares(int m) {
  TestScene t;
  t.scene.source = "parallel squares";
  t.scene.materials = {test::grey(0.5, 1.0)};
  addGrid(t.patches, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, m, m);
  addGrid(t.patches, {0, 0, 1}, {0, 1, 0}, {1, 0, 0}, 1, 1);  // facing down
  return t;
}

TestScene perpendicularSquares(int m) {
  TestScene t;
  t.scene.source = "perpendicular squares";
  t.scene.materials = {test::grey(0.5, 1.0)};
  addGrid(t.patches, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, m, m);
  addGrid(t.patches, {0, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1, 1);  // the wall x = 0, facing +x
  return t;
}

TEST(AnalyticFormFactor, ParallelAndPerpendicularUnitSquaresMatchTheirClosedForms) {
  const double parallel = test::parallelRectanglesFormFactor(1, 1, 1);
  const double perpendicular = test::perpendicularRectanglesFormFactor(1, 1, 1);
  EXPECT_NEAR(parallel, 0.1998, 5e-5);
  EXPECT_NEAR(perpendicular, 0.2000, 5e-5);
  const SolveOptions analytic = test::optionsFor(Projection::Analytic);
  double previousParallel = 1.0, previousPerpendicular = 1.0;
  for (int m : {4, 12, 36}) {  // midpoint quadrature over the shooter: the error shrinks with m
    const double p = areaFormFactor(parallelSquares(m), analytic, range(0, m * m), {m * m});
    const double q = areaFormFactor(perpendicularSquares(m), analytic, range(0, m * m), {m * m});
    EXPECT_LT(std::abs(p - parallel), previousParallel) << m;
    EXPECT_LT(std::abs(q - perpendicular), previousPerpendicular) << m;
    previousParallel = std::abs(p - parallel);
    previousPerpendicular = std::abs(q - perpendicular);
  }
  EXPECT_LT(previousParallel, 5e-5);
  EXPECT_LT(previousPerpendicular, 2e-4);
}

TEST(AnalyticFormFactor, ReciprocityOfAreaFormFactors) {
  // A 1 x 1 square and a 2 x 0.5 rectangle, tilted and apart: A_i F_ij = A_j F_ji.
  TestScene t;
  t.scene.source = "two rectangles";
  t.scene.materials = {test::grey(0.5, 1.0)};
  const int m = 16;
  addGrid(t.patches, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, m, m);
  addGrid(t.patches, {-0.5, 0.3, 1.2}, {0, 0.5, 0.2}, {2, 0, 0}, m, m);
  const SolveOptions analytic = test::optionsFor(Projection::Analytic);
  const auto a = range(0, m * m), b = range(m * m, 2 * m * m);
  const double areaA = 1.0, areaB = 2.0 * glm::length(Vec3(0, 0.5, 0.2));
  const double ab = areaA * areaFormFactor(t, analytic, a, b);
  const double ba = areaB * areaFormFactor(t, analytic, b, a);
  EXPECT_GT(ab, 0.05);
  EXPECT_NEAR(ab, ba, 1e-3 * ab);
}

std::vector<Vec3> rectangle(Vec3 corner, Vec3 side1, Vec3 side2) {
  return {corner, corner + side1, corner + side1 + side2, corner + side2};
}

double polygonForm(const std::vector<Vec3>& from, const std::vector<Vec3>& to) {
  return polygonToPolygonFormFactor(from, to);
}

TEST(AnalyticFormFactor, PolygonToPolygonMatchesTheClosedFormsHoweverNarrowTheGap) {
  for (double c : {1.0, 0.1, 0.01, 0.001}) {
    // Directly opposed, a 1 x 1 square and a 2 x 0.5 rectangle, c apart, the upper facing down.
    const double square =
        polygonForm(rectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), rectangle({0, 0, c}, {0, 1, 0}, {1, 0, 0}));
    EXPECT_NEAR(square, test::parallelRectanglesFormFactor(1, 1, c), 1e-9) << "c " << c;
    const double strip =
        polygonForm(rectangle({0, 0, 0}, {2, 0, 0}, {0, 0.5, 0}), rectangle({0, 0, c}, {0, 0.5, 0}, {2, 0, 0}));
    EXPECT_NEAR(strip, test::parallelRectanglesFormFactor(2, 0.5, c), 1e-9) << "c " << c;
    // A floor 1 x 1 and a wall standing c above it on its edge x = 0, 0.5 high: the wall from 0 to
    // c + 0.5 less the wall from 0 to c (form factors to parts of a plane add).
    const double wall =
        polygonForm(rectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), rectangle({0, 0, c}, {0, 1, 0}, {0, 0, 0.5}));
    const double exactWall =
        test::perpendicularRectanglesFormFactor(1, c + 0.5, 1) - test::perpendicularRectanglesFormFactor(1, c, 1);
    EXPECT_NEAR(wall, exactWall, 1e-9) << "c " << c;
  }
}

TEST(AnalyticFormFactor, PolygonToPolygonIsReciprocalAndBlindToWinding) {
  const std::vector<Vec3> triangle{{0, 0, 0}, {1.2, 0.1, 0}, {0.3, 0.9, 0}};
  // A parallelogram above it, tilted, facing down and wholly in front of it.
  const std::vector<Vec3> tilted = rectangle({-0.2, 0.1, 0.6}, {0.1, 0.7, 0.2}, {0.9, 0.1, -0.1});
  const double areaTriangle = 0.5 * glm::length(glm::cross(triangle[1] - triangle[0], triangle[2] - triangle[0]));
  const double areaTilted = glm::length(glm::cross(tilted[1] - tilted[0], tilted[3] - tilted[0]));
  const double f = polygonForm(triangle, tilted);
  EXPECT_GT(f, 0.1);
  EXPECT_NEAR(areaTriangle * f, areaTilted * polygonForm(tilted, triangle), 1e-12);
  EXPECT_NEAR(polygonForm({triangle.rbegin(), triangle.rend()}, tilted), f, 1e-12);
  EXPECT_NEAR(polygonForm(triangle, {tilted.rbegin(), tilted.rend()}), f, 1e-12);
}

TEST(AnalyticFormFactor, RowsOfAClosedBoxSumToOne) {
  const TestScene box = test::closedBox({1.0, 1.3, 0.9}, 3, {test::grey(0.5, 1.0)});
  const SolveOptions analytic = test::optionsFor(Projection::Analytic);
  for (const FormFactorRow& row : test::rowsOf(box, analytic, range(0, static_cast<int>(box.patches.size())))) {
    EXPECT_NEAR(row.hitFraction(), 1.0, 1e-9) << "shooter " << row.shooter;
    EXPECT_EQ(row.backFaces, 0.0);
  }
}

TEST(AnalyticFormFactor, RefusesAScenePatchesHideEachOtherIn) {
  // A box with a floating panel inside: seen from the floor, the panel hides part of the ceiling.
  TestScene t = test::closedBox({1, 1, 1}, 2, {test::grey(0.5, 1.0)});
  t.scene.polygons.push_back({{{0.3, 0.3, 0.5}, {0.7, 0.3, 0.5}, {0.7, 0.7, 0.5}, {0.3, 0.7, 0.5}}, 0, "line 7: panel"});
  addGrid(t.patches, {0.3, 0.3, 0.5}, {0, 0.4, 0}, {0.4, 0, 0}, 1, 1, 0, 6);  // facing down
  try {
    test::rowsOf(t, test::optionsFor(Projection::Analytic), {0});
    FAIL() << "a non-convex scene was accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.file(), "test box");
    EXPECT_NE(std::string(e.what()).find("not a convex enclosure"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--projection hemicube"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace radmesh
