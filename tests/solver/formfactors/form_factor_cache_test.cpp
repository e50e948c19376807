#include "solver/formfactors/form_factor_cache.h"

#include <gtest/gtest.h>

namespace radmesh {
namespace {

FormFactorRow row(int shooter, int receivers) {
  FormFactorRow r;
  r.shooter = shooter;
  for (int j = 0; j < receivers; ++j) {
    r.receivers.push_back(j);
    r.formFactors.push_back(1.0 / receivers);
  }
  return r;
}

TEST(FormFactorCache, KeepsRowsWithinBudgetDroppingTheLeastRecentlyUsed) {
  const FormFactorRow made = row(0, 100);
  const FormFactorRow kept = made;  // a copy, as the cache keeps: no spare capacity
  const std::size_t one = kept.bytes();
  FormFactorCache cache(2 * one + one / 2);  // room for two rows
  cache.insert(row(1, 100));
  cache.insert(row(2, 100));
  ASSERT_NE(cache.find(1), nullptr);  // 1 is now the most recently used
  cache.insert(row(3, 100));          // drops 2
  EXPECT_EQ(cache.find(2), nullptr);
  ASSERT_NE(cache.find(1), nullptr);
  ASSERT_NE(cache.find(3), nullptr);
  EXPECT_EQ(cache.find(1)->formFactors.size(), 100u);
  EXPECT_EQ(cache.rows(), 2u);
  EXPECT_LE(cache.bytes(), 2 * one + one / 2);
}

// After a split round: rows reaching a split receiver go, the others are renumbered, in the same
// order of use and within the same bytes.
TEST(FormFactorCache, RenumbersReceiversDroppingRowsThatReachSplitOnes) {
  FormFactorCache cache(1 << 20);
  cache.insert(row(1, 3));  // receivers 0, 1, 2
  cache.insert(row(2, 2));  // receivers 0, 1
  const std::size_t bytes = cache.bytes();
  cache.insert(row(3, 4));  // reaches receiver 3, which splits
  FormFactorRow binned = row(4, 2);  // a portal's row: its bins reach receiver 3 too
  binned.binShares = {{1, 0, 0.25}, {3, 1, 0.5}};
  cache.insert(binned);
  FormFactorRow kept = row(5, 2);
  kept.binShares = {{0, 2, 0.25}, {1, 0, 0.5}};
  cache.insert(kept);
  cache.renumberReceivers({0, 4, 5, -1});  // 0 stays, 3 new receivers before 1 and 2 (its children)
  EXPECT_EQ(cache.find(3), nullptr);
  EXPECT_EQ(cache.find(4), nullptr);
  ASSERT_NE(cache.find(5), nullptr);
  EXPECT_EQ(cache.find(5)->binShares[0].patch, 0);
  EXPECT_EQ(cache.find(5)->binShares[1].patch, 4);
  cache.erase(5);
  EXPECT_EQ(cache.rows(), 2u);
  EXPECT_EQ(cache.bytes(), bytes);
  ASSERT_NE(cache.find(1), nullptr);
  EXPECT_EQ(cache.find(1)->receivers, (std::vector<int>{0, 4, 5}));
  EXPECT_EQ(cache.find(2)->receivers, (std::vector<int>{0, 4}));
  EXPECT_EQ(cache.contents().front().shooter, 2);  // found last
  cache.erase(2);
  EXPECT_EQ(cache.find(2), nullptr);
  EXPECT_EQ(cache.rows(), 1u);
}

TEST(FormFactorCache, RowLargerThanTheBudgetIsNotKept) {
  FormFactorCache cache(1000);
  cache.insert(row(1, 1000));
  EXPECT_EQ(cache.find(1), nullptr);
  EXPECT_EQ(cache.bytes(), 0u);
  FormFactorCache none(0);
  none.insert(row(1, 1));
  EXPECT_EQ(none.rows(), 0u);
}

}  // namespace
}  // namespace radmesh
