#include "emulator/mesh_sort.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "tests/emulator/plural_compare.h"

namespace radmesh::emu {
namespace {

using Pair = std::pair<int, int>;

TEST(SortPairs, OnePerPeMatchesStdSortAndKeepsEveryPair) {
  MeshMachine m({16, 8});
  const auto keys = test::randomInts(128, 0, 40, 12);  // many equal keys
  Plural<int> k(m), v(m);
  test::load(k, keys);
  for (int pe = 0; pe < 128; ++pe) v[pe] = 1000 * keys[pe] + pe;  // value remembers its key
  sortPairs(m, k, v);
  std::vector<int> expected = keys;
  std::sort(expected.begin(), expected.end());
  EXPECT_TRUE(test::samePerPe(m.grid(), k, expected));
  std::vector<int> values(v.data(), v.data() + 128), original(128);
  for (int pe = 0; pe < 128; ++pe) {
    EXPECT_EQ(v[pe] / 1000, k[pe]) << "value travelled without its key at " << m.grid().name(pe);
    original[pe] = 1000 * keys[pe] + pe;
  }
  std::sort(values.begin(), values.end());
  std::sort(original.begin(), original.end());
  EXPECT_EQ(values, original);  // the same multiset of pairs
}

TEST(SortPairs, ListsOfFourPerPeSortInPeThenSlotOrder) {
  MeshMachine m({8, 8});
  const auto keys = test::randomInts(256, -1000, 1000, 13);
  PeArray<int> k(m, "keys");
  PeArray<double> v(m, "values");
  for (int i = 0; i < 256; ++i) k.push(i / 4, keys[i]), v.push(i / 4, keys[i] * 0.5);
  sortPairs(m, k, v);
  std::vector<int> expected = keys;
  std::sort(expected.begin(), expected.end());
  for (int i = 0; i < 256; ++i) {
    ASSERT_EQ(k.at(i / 4, i % 4), expected[i]) << "first difference at element " << i << ", "
                                               << m.grid().name(i / 4);
    ASSERT_EQ(v.at(i / 4, i % 4), expected[i] * 0.5);
  }
}

TEST(SortPairs, InactivePesKeepTheirPairsAndActiveOnesReceiveTheSortedOnes) {
  MeshMachine m({8, 8});
  const auto keys = test::randomInts(64, 0, 500, 14);
  Plural<int> k(m), v(m);
  test::load(k, keys);
  test::load(v, keys);
  const Plural<bool> cond = test::randomCondition(m, 0.5, 15);
  {
    ActiveScope scope(m, cond);
    sortPairs(m, k, v);
  }
  std::vector<int> activeKeys;
  for (int pe = 0; pe < 64; ++pe)
    if (cond[pe]) activeKeys.push_back(keys[pe]);
  std::sort(activeKeys.begin(), activeKeys.end());
  std::vector<int> expected = keys;
  std::size_t next = 0;
  for (int pe = 0; pe < 64; ++pe)
    if (cond[pe]) expected[pe] = activeKeys[next++];
  EXPECT_TRUE(test::samePerPe(m.grid(), k, expected));
  EXPECT_TRUE(test::samePerPe(m.grid(), v, expected));
  EXPECT_GT(m.costs().sort.messages, 0);  // the placement went through the router
}

TEST(SortPairs, RefusesNonPowerOfTwoShapes) {
  MeshMachine m({6, 8});
  Plural<int> k(m), v(m);
  EXPECT_THROW(sortPairs(m, k, v), std::invalid_argument);
  MeshMachine square({4, 4});
  PeArray<int> k3(square, 3, 0, "k"), v3(square, 3, 0, "v");
  EXPECT_THROW(sortPairs(square, k3, v3), std::invalid_argument);
}

TEST(SortPairs, CostIsTheBitonicNetworkOnTheMesh) {
  // 4 x 4 PEs, one int pair (8 bytes) each: n = 16, stages (size, j): (2,1) (4,2) (4,1) (8,4)
  // (8,2) (8,1) (16,8) (16,4) (16,2) (16,1). PE distance j: 1, 2 along a row; 4, 8 are rows 1, 2.
  MeshMachine m({4, 4});
  Plural<int> k(m), v(m);
  sortPairs(m, k, v);
  const ClassCounts c = m.costs().sort;
  const std::int64_t hops = 2 * (1 + 2 + 1 + 1 + 2 + 1 + 2 + 1 + 2 + 1);
  EXPECT_EQ(c.ops, 1);
  EXPECT_EQ(c.hops, hops);
  EXPECT_EQ(c.byteHops, hops * 8);
  EXPECT_EQ(c.intOps, 10.0);
  EXPECT_EQ(c.messages, 0);
}

}  // namespace
}  // namespace radmesh::emu
