#include "emulator/reduce.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/emulator/plural_compare.h"

namespace radmesh::emu {
namespace {

TEST(ReduceMax, FindsTheMaximumAndTheLowestIndexAmongTies) {
  MeshMachine m({8, 8});
  Plural<int> v(m);
  test::load(v, test::randomInts(64, 0, 20, 3));
  v[17] = 50;
  v[40] = 50;
  v[63] = 50;
  const Located<int> best = reduceMax(m, v);
  EXPECT_EQ(best.value, 50);
  EXPECT_EQ(best.pe, 17);
}

TEST(ReduceMax, ConsidersActivePesOnly) {
  MeshMachine m({8, 8});
  Plural<double> v(m);
  for (int pe = 0; pe < 64; ++pe) v[pe] = std::sin(pe * 1.7);
  const Plural<bool> cond = test::randomCondition(m, 0.3, 8);
  Located<double> expected;
  for (int pe = 0; pe < 64; ++pe)
    if (cond[pe] && (expected.pe < 0 || v[pe] > expected.value)) expected = {v[pe], pe};
  ActiveScope scope(m, cond);
  const Located<double> best = reduceMax(m, v);
  EXPECT_EQ(best.pe, expected.pe);
  EXPECT_EQ(best.value, expected.value);
}

TEST(ReduceMax, NoActivePeGivesIndexMinusOne) {
  MeshMachine m({2, 2});
  Plural<int> v(m, 4);
  ActiveScope scope(m, Plural<bool>(m, false));
  EXPECT_EQ(reduceMax(m, v).pe, -1);
}

TEST(ReduceMax, RefusesNaNNamingThePe) {
  MeshMachine m({4, 4});
  Plural<double> v(m, 1.0);
  v[9] = std::nan("");
  try {
    reduceMax(m, v);
    FAIL() << "expected std::domain_error";
  } catch (const std::domain_error& e) {
    EXPECT_NE(std::string(e.what()).find("PE (row 2, col 1)"), std::string::npos) << e.what();
  }
}

TEST(ReduceAdd, SumsActivePesInRowMajorOrder) {
  MeshMachine m({8, 8});
  Plural<double> v(m);
  for (int pe = 0; pe < 64; ++pe) v[pe] = 1.0 / (pe + 1.0) * (pe % 2 ? 1e8 : 1e-8);
  const Plural<bool> cond = test::randomCondition(m, 0.5, 4);
  double expected = 0.0;
  for (int pe = 0; pe < 64; ++pe)
    if (cond[pe]) expected += v[pe];
  ActiveScope scope(m, cond);
  EXPECT_EQ(reduceAdd(m, v), expected);  // bit-identical: same order
}

TEST(ReduceAdd, IntegerSumIsExact) {
  MeshMachine m({16, 16});
  Plural<long long> v(m);
  long long expected = 0;
  for (int pe = 0; pe < 256; ++pe) v[pe] = pe * 1'000'003LL, expected += v[pe];
  EXPECT_EQ(reduceAdd(m, v), expected);
}

}  // namespace
}  // namespace radmesh::emu
