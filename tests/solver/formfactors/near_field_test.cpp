// The near-field finder (solver/formfactors/near_field.h) on stacks of parallel copies, as an MGF
// array makes them: which pairs it finds, and how many receivers it had to measure to find them.
#include "solver/formfactors/near_field.h"

#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "tests/solver/patch_fixtures.h"

namespace radmesh::test {
namespace {

// A unit square facing down at height z, like a ceiling lamp.
Patch lampAt(double z) { return makePatch({{0, 0, z}, {0, 1, z}, {1, 1, z}, {1, 0, z}}); }

TEST(NearField, StackedParallelCopiesAreNotNearAndNotMeasured) {
  // 200 lamps 1 mm apart, 0.5 m above a floor square facing up: each lamp faces the floor, no lamp
  // faces another (each is behind the one it is in front of).
  constexpr int kLamps = 200;
  std::vector<Patch> patches{makePatch({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}})};
  for (int k = 0; k < kLamps; ++k) patches.push_back(lampAt(0.5 + 0.001 * k));
  NearFieldFinder finder(patches, patches);
  std::vector<int> lamps(kLamps);
  std::iota(lamps.begin(), lamps.end(), 1);
  EXPECT_EQ(finder.receiversNear(0), lamps);
  for (int k = 1; k <= kLamps; ++k) ASSERT_EQ(finder.receiversNear(k), std::vector<int>{0}) << "lamp " << k;
  // The floor measures itself and every lamp, each lamp the floor alone: its parallel copies are
  // passed over whole (measuring them all was 201 x 201).
  EXPECT_EQ(finder.receiversExamined(), 1u + 2u * kLamps);
}

TEST(NearField, StackedCopiesThatAreNotFlatStillFindEachOther) {
  // A quad with one corner 1 micrometre off the plane of the others, and 9 copies 10 nm apart above
  // it: the raised corner of each is in front of every other, so all are near, parallel as they are.
  constexpr int kCopies = 10;
  std::vector<Patch> patches;
  for (int k = 0; k < kCopies; ++k) {
    const double z = 1e-8 * k;
    patches.push_back(makePatch({{0, 0, z}, {1, 0, z}, {1, 1, z + 1e-6}, {0, 1, z}}));
  }
  NearFieldFinder finder(patches, patches);
  for (int k = 0; k < kCopies; ++k) {
    std::vector<int> others;
    for (int j = 0; j < kCopies; ++j)
      if (j != k) others.push_back(j);
    EXPECT_EQ(finder.receiversNear(k), others) << "copy " << k;
  }
  EXPECT_EQ(finder.receiversExamined(), size_t{kCopies * kCopies});
}

}  // namespace
}  // namespace radmesh::test
