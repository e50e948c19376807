// --element-rows share (solver/formfactors/element_shares.h): each patch's form factor shared among
// its elements, against the rasterised elements and the closed forms; the cheaper closed forms it
// and the near field rest on.
#include "solver/formfactors/element_shares.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "solver/backends/native/native_backend.h"
#include "solver/formfactors/analytic_form_factor.h"
#include "solver/formfactors/near_field.h"
#include "solver/projection/environment_projection.h"
#include "solver/projection/hemicube.h"
#include "solver/projection/scan_conversion.h"
#include "tests/solver/closed_forms.h"
#include "tests/solver/solver_test_helpers.h"

namespace radmesh::test {
namespace {

// A square of side s, centred at distance r on a ray at angle theta off the normal, tilted by tilt.
std::vector<Vec3> squareAt(double s, double r, double theta, double tilt) {
  const Vec3 c(r * std::sin(theta), 0.0, r * std::cos(theta));
  const Vec3 u(1, 0, 0), v(0, std::cos(tilt), std::sin(tilt));
  return {c - 0.5 * s * u - 0.5 * s * v, c + 0.5 * s * u - 0.5 * s * v, c + 0.5 * s * u + 0.5 * s * v,
          c - 0.5 * s * u + 0.5 * s * v};
}

TEST(AnalyticFormFactor, ASmallPolygonFarAwayTakesTheDifferentialFormWithinThreeTenthsOfAPercent) {
  for (double theta : {0.0, 0.6, 1.2})
    for (double tilt : {0.0, 0.5, 1.0}) {
      // The diameter just within kSmallPolygonRatio of the distance: the differential form.
      const double r = 2.0, s = 0.99 * kSmallPolygonRatio * r / std::sqrt(2.0);
      const std::vector<Vec3> square = squareAt(s, r, theta, tilt);
      const Vec3 centroid = 0.25 * (square[0] + square[1] + square[2] + square[3]);
      const Vec3 normal = glm::normalize(glm::cross(square[1] - square[0], square[2] - square[1]));
      const double exact = pointToPolygonFormFactor(square);
      const double small = smallPolygonFormFactor(square, centroid, normal, s * s);
      ASSERT_GT(exact, 0.0);
      EXPECT_NE(small, exact);  // the differential form, not the closed one
      EXPECT_NEAR(small, exact, 3e-3 * exact) << "theta " << theta << ", tilt " << tilt;
      // Larger, or reaching behind the origin's plane: the closed form itself.
      const std::vector<Vec3> large = squareAt(1.2 * kSmallPolygonRatio * r, r, theta, tilt);
      const Vec3 largeCentroid = 0.25 * (large[0] + large[1] + large[2] + large[3]);
      EXPECT_EQ(smallPolygonFormFactor(large, largeCentroid, normal, 1.0), pointToPolygonFormFactor(large));
    }
}

// A 1 x 1 floor shooting to a strip of the wall it meets along a whole edge, 1 m long and h high:
// Howell's closed form. The strip, smaller than the shooter, is sampled by reciprocity.
TEST(NearField, AReceiverSmallerThanTheShooterIsSampledByReciprocityToTheClosedForm) {
  const Patch floor = makePatch({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)});
  for (double h : {0.05, 0.2, 0.6}) {
    const Patch strip = makePatch({Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(0, 1, h), Vec3(0, 0, h)});  // x = 0, facing +x
    const double exact = perpendicularRectanglesFormFactor(1.0, h, 1.0);
    // Measured 1.14 %, 0.78 % and 0.25 % high: the strip's points nearest the shared edge.
    EXPECT_NEAR(areaToAreaFormFactor(floor, strip), exact, 0.015 * exact) << "h " << h;
  }
}

// 1 m plates 1 cm apart: points sampled 0.125 m apart (8 cuts) read 0.99521 for 0.98042. Apart across
// a gap under that spacing, a pair takes the exact contour integral; a wider gap keeps the sampling.
TEST(NearField, PlatesAcrossAGapNarrowerThanTheSamplesTakeTheExactFormFactor) {
  const Patch floor = makePatch({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)});
  auto plate = [](double h, double side) {  // facing down
    return makePatch({Vec3(0, 0, h), Vec3(0, side, h), Vec3(side, side, h), Vec3(side, 0, h)});
  };
  for (double h : {0.01, 0.001, 0.1}) {
    const double exact = parallelRectanglesFormFactor(1, 1, h);
    EXPECT_NEAR(areaToAreaFormFactor(floor, plate(h, 1.0)), exact, 1e-9) << "h " << h;
    EXPECT_NEAR(areaToAreaFormFactor(plate(h, 1.0), floor), exact, 1e-9) << "h " << h;
  }
  // 0.2 m apart, the sampling's own error: 0.57 % high.
  const double wide = parallelRectanglesFormFactor(1, 1, 0.2);
  EXPECT_NEAR(areaToAreaFormFactor(floor, plate(0.2, 1.0)), 1.0057 * wide, 1e-4 * wide);
}

// A floor cell a quarter under a block, and the block's side, as large as the cell to rounding: the
// quarter behind the side's plane sees its back and sends its front nothing, whichever of the two is
// sampled, and the choice of which does not turn on rounding.
TEST(NearField, AShooterPartlyBehindTheReceiversPlaneSendsItNothingFromThere) {
  const Patch floor = makePatch({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)});
  auto side = [](double h) { return makePatch({Vec3(0.25, 0, 0), Vec3(0.25, 1, 0), Vec3(0.25, 1, h), Vec3(0.25, 0, h)}); };
  const double exact = 0.75 * perpendicularRectanglesFormFactor(0.75, 1.0, 1.0);  // from the part x > 0.25
  const double f = areaToAreaFormFactor(floor, side(1.0));
  EXPECT_NEAR(f, exact, 0.01 * exact);
  for (double h : {1.0 - 1e-9, 1.0 + 1e-9}) EXPECT_NEAR(areaToAreaFormFactor(floor, side(h)), f, 1e-7 * f) << "h - 1 = " << h - 1;
}

// Near receivers found in groups of shooters by size are those of the definition
// (near_field.h), checked pair by pair, among patches from 0.02 m to 3 m; each 3 m patch has 0.02
// to 0.3 m ones facing it a little above, near its edge, where only its nearest point is near them.
TEST(NearField, ReceiversFoundInGroupsBySizeAreThoseOfTheDefinition) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> position(0.0, 4.0), unit(-1.0, 1.0), fraction(0.0, 1.0);
  TestScene t;
  for (int k = 0; k < 400; ++k) {
    const double side = k % 50 == 0 ? 3.0 : 0.02 + 0.3 * (k % 7) / 7.0;
    const Vec3 u = side * glm::normalize(Vec3(unit(random), unit(random), unit(random)));
    const Vec3 v = side * glm::normalize(glm::cross(u, Vec3(unit(random), unit(random), unit(random))));
    const Vec3 corner(position(random), position(random), position(random));
    addGrid(t.patches, corner, u, v, 1, 1);
    if (side < 3.0) continue;
    const Vec3 n = glm::normalize(glm::cross(u, v));
    for (int m = 0; m < 7; ++m) {
      const double small = 0.02 + 0.3 * m / 7.0;
      const Vec3 above = corner + (0.02 + 0.05 * fraction(random)) * u + fraction(random) * v + 0.1 * fraction(random) * n;
      addGrid(t.patches, above, small / side * v, small / side * u, 1, 1);  // facing the large one
    }
  }
  const auto near = findNearFieldReceivers(t.patches);
  size_t pairs = 0, byNearestPoint = 0;
  for (size_t i = 0; i < t.patches.size(); ++i) {
    const Patch& s = t.patches[i];
    double size = 0.0;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) size = std::max(size, glm::length(s.vertices[a] - s.vertices[b]));
    auto partlyInFront = [&](const Patch& p, const Patch& of) {
      for (int k = 0; k < 4; ++k)
        if (glm::dot(p.vertices[k] - of.centroid, of.normal) > 1e-9 * size) return true;
      return false;
    };
    std::vector<int> expected;
    for (size_t j = 0; j < t.patches.size(); ++j)
      if (j != i && inNearField(s, size, t.patches[j]) && partlyInFront(t.patches[j], s) && partlyInFront(s, t.patches[j]))
        expected.push_back(static_cast<int>(j));
    EXPECT_EQ(near[i], expected) << "shooter " << i;
    pairs += expected.size();
    for (int j : expected) byNearestPoint += glm::length(t.patches[j].centroid - s.centroid) >= size;
  }
  EXPECT_GT(pairs, 100u);  // the test sees pairs, and the large patches' among them
  EXPECT_GT(byNearestPoint, 20u) << pairs;  // receivers whose centroids are beyond the shooter's size
}

// A shooter's near pairs are computed for the near receivers its rows reach, each once: a receiver
// the row does not list (hidden, or unseen) costs nothing until a row reaches it.
TEST(NearField, PairsAreComputedForTheNearReceiversARowReachesOnce) {
  const Patch floor = makePatch({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)});
  const std::vector<Patch> receivers = {
      makePatch({Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(0, 1, 0.2), Vec3(0, 0, 0.2)}),    // a wall strip, x = 0
      makePatch({Vec3(1, 1, 0), Vec3(1, 0, 0), Vec3(1, 0, 0.2), Vec3(1, 1, 0.2)})};   // another, x = 1
  const std::vector<int> near = {0, 1};
  FormFactorRow row;
  row.receivers = {1};
  row.formFactors = {0.1};
  std::vector<NearFieldPair> pairs;
  completeNearFieldPairs(floor, receivers, near, row, pairs);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_FALSE(pairs[0].computed);
  ASSERT_TRUE(pairs[1].computed);
  EXPECT_EQ(pairs[1].area, areaToAreaFormFactor(floor, receivers[1]));
  EXPECT_EQ(pairs[1].point, pointToPolygonFormFactor(toShooterFrame(floor, receivers[1]).corners()));
  pairs[1].area = -1.0;  // a marker: a pair computed already is kept, not computed again
  row.receivers = {0, 1};
  row.formFactors = {0.1, 0.1};
  completeNearFieldPairs(floor, receivers, near, row, pairs);
  EXPECT_TRUE(pairs[0].computed);
  EXPECT_EQ(pairs[0].area, areaToAreaFormFactor(floor, receivers[0]));
  EXPECT_EQ(pairs[1].area, -1.0);
}

// The rows over elements: each patch's elements together receive exactly what the patch does in a
// projection of the patches (so shots, ledger and patches' answer are the patch projection's),
// and closer to the closed forms than the rasterised elements.
TEST(ElementShares, EachPatchsElementsReceiveExactlyThePatchsFormFactor) {
  const TestScene t = closedBox(Vec3(1.0), 2, {grey(0.6), grey(0.3, 10.0)}, {0, 1, 0, 0, 0, 0});
  for (Projection projection : {Projection::Plane, Projection::Hemicube}) {
    SCOPED_TRACE(toString(projection));
    const SolveOptions patchesOnly = optionsFor(projection, 64);
    const SolveOptions shared = subdivided(patchesOnly, Subdivide::Uniform, 0.2);
    const Elements elements = subdivideUniform(t.patches, 0.2);
    NativeBackend patchBackend(t.scene, t.patches, patchesOnly), elementBackend(t.scene, t.patches, elements, shared);
    std::vector<FormFactorRow> patchRows, elementRows;
    patchBackend.computeRows(range(0, 24), patchRows);
    elementBackend.computeRows(range(0, 24), elementRows);
    for (size_t s = 0; s < patchRows.size(); ++s) {
      std::vector<double> sums(t.patches.size(), 0.0);
      for (size_t r = 0; r < elementRows[s].receivers.size(); ++r)
        sums[elements.patchOf[elementRows[s].receivers[r]]] += elementRows[s].formFactors[r];
      for (int p = 0; p < static_cast<int>(t.patches.size()); ++p)
        EXPECT_NEAR(sums[p], entry(patchRows[s], p), 1e-15) << "shooter " << s << ", patch " << p;
      EXPECT_EQ(elementRows[s].capturedFraction, patchRows[s].capturedFraction);
    }
  }
}

// What sharing tells a whole patch from a partly hidden one by: per patch, the pixel centres its
// projection covers (covers(), pixel by pixel) and those of them that show it.
TEST(ElementShares, TheProjectionCountsThePixelsEachPatchCoversAndShows) {
  TestScene t;
  addGrid(t.patches, Vec3(-0.1, -0.1, 0), Vec3(0.2, 0, 0), Vec3(0, 0.2, 0), 1, 1);    // the shooter, facing up
  addGrid(t.patches, Vec3(-1, -1, 1), Vec3(0, 2, 0), Vec3(2, 0, 0), 1, 1);           // a ceiling, facing down
  addGrid(t.patches, Vec3(0.1, 0.1, 0.5), Vec3(0, 0.4, 0), Vec3(0.4, 0, 0), 1, 1);  // under part of it
  ThreadPool pool(1);
  EnvironmentProjection projection(t.patches, makeHemicube(64), sceneNearDepth(t.patches), pool);
  projection.project(0);
  for (int p : {1, 2}) {
    long long covered = 0, shown = 0;
    unsigned faces = 0;
    const LocalPolygon local = toShooterFrame(t.patches[0], t.patches[p]);
    for (size_t f = 0; f < projection.surface().faces.size(); ++f) {
      const ProjectionFace& face = projection.surface().faces[f];
      PolygonSetup setup;
      if (!setUpProjection(local, face, sceneNearDepth(t.patches), p, 0, setup)) continue;
      faces |= 1u << f;
      for (int row = 0; row < face.height; ++row)
        for (int column = 0; column < face.width; ++column)
          if (covers(setup, column, row)) {
            ++covered;
            shown += projection.itemBuffers()[f].item(column, row) == p;
          }
    }
    EXPECT_EQ(projection.coveredPixels()[p], covered) << "patch " << p;
    EXPECT_EQ(projection.shownPixels()[p], shown) << "patch " << p;
    EXPECT_EQ(projection.facesReached()[p], faces) << "patch " << p;
  }
  EXPECT_EQ(projection.facesReached()[1], 0b11111u);  // the ceiling reaches past every side face's edge
  EXPECT_LT(projection.shownPixels()[1], projection.coveredPixels()[1]);   // the ceiling, partly hidden
  EXPECT_EQ(projection.shownPixels()[2], projection.coveredPixels()[2]);   // the occluder, whole
  EXPECT_GT(projection.shownPixels()[2], 100);
}

// A patch the item buffer shows whole shares by its elements' closed forms (smallPolygonFormFactor
// from the shooter's centroid), whether near (each element the exact closed form) or far and small
// against its distance (each the differential form, found without its corners).
TEST(ElementShares, AWholePatchSharesInProportionToItsElementsClosedForms) {
  TestScene t;
  addGrid(t.patches, Vec3(-0.1, -0.1, 0), Vec3(0.2, 0, 0), Vec3(0, 0.2, 0), 1, 1);      // the shooter, facing up
  addGrid(t.patches, Vec3(-1, -1, 1), Vec3(0, 2, 0), Vec3(2, 0, 0), 1, 1);             // a ceiling, facing down
  addGrid(t.patches, Vec3(0.3, 0.2, 0.9), Vec3(0, 0.05, 0), Vec3(0.05, 0, 0), 1, 1);   // a far, small tile
  addGrid(t.patches, Vec3(-0.6, -0.1, 0.4), Vec3(0, 0.2, 0), Vec3(0.2, 0, 0), 1, 1);   // a near one
  const Elements elements = subdivideUniform(t.patches, 0.025);
  ThreadPool pool(1);
  const double nearDepth = sceneNearDepth(t.patches);
  EnvironmentProjection projection(t.patches, makeHemicube(64), nearDepth, pool);
  projection.project(0);
  const Occluders occluders(t.patches);
  const ProjectedShot shot{t.patches, t.patches[0], projection.surface(), projection.itemBuffers(),
                           projection.projectedAreaPixels(),
                           projection.projectedWidthPixels(), projection.coveredPixels(), projection.shownPixels(),
                           occluders};
  const PatchShot patchShot{projection.pixelFormFactors(), projection.seenFromFront(), projection.coveredPixels(),
                            projection.shownPixels(), projection.facesReached()};
  std::vector<double> formFactors;
  std::vector<char> front;
  shareAmongElements(shot, nearDepth, patchShot, elements, pool, formFactors, front);
  const double tileDiameter = 0.05 * std::sqrt(2.0);
  ASSERT_LT(tileDiameter, kSmallPolygonRatio * (glm::length(t.patches[2].centroid) - tileDiameter));  // far
  for (int p : {2, 3}) {
    SCOPED_TRACE(p);
    ASSERT_EQ(projection.shownPixels()[p], projection.coveredPixels()[p]);  // whole
    const int begin = elements.first[p], end = elements.first[p + 1];
    ASSERT_GE(end - begin, 4);
    std::vector<double> closed;
    double sum = 0.0;
    for (int e = begin; e < end; ++e) {
      const LocalPolygon local = toShooterFrame(t.patches[0], elements.elements[e]);
      closed.push_back(smallPolygonFormFactor(local.corners(), local.centroid, local.normal, elements.elements[e].areaM2));
      sum += closed.back();
    }
    for (int e = begin; e < end; ++e) {
      EXPECT_DOUBLE_EQ(formFactors[e], projection.pixelFormFactors()[p] * closed[e - begin] / sum);
      EXPECT_EQ(front[e], 1);
    }
  }
}

}  // namespace
}  // namespace radmesh::test
