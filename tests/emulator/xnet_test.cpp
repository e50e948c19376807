#include "emulator/xnet.h"

#include <gtest/gtest.h>

#include "emulator/cost_model.h"
#include "tests/emulator/plural_compare.h"

namespace radmesh::emu {
namespace {

using test::samePerPe;

// The scalar meaning of a shift, written without PeGrid: data moves `distance` hops toward
// `direction`, so PE (r, c) receives what PE (r - dRow*d, c - dCol*d) held, modulo the torus.
std::vector<int> shiftedReference(int rows, int cols, const std::vector<int>& src, int dRow,
                                  int dCol, int distance) {
  std::vector<int> out(src.size());
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      int sr = (r - dRow * distance) % rows;
      int sc = (c - dCol * distance) % cols;
      if (sr < 0) sr += rows;
      if (sc < 0) sc += cols;
      out[r * cols + c] = src[sr * cols + sc];
    }
  return out;
}

struct DirectionCase {
  Direction direction;
  int dRow;
  int dCol;
};
const DirectionCase kCases[] = {{Direction::N, -1, 0}, {Direction::NE, -1, 1},
                                {Direction::E, 0, 1},  {Direction::SE, 1, 1},
                                {Direction::S, 1, 0},  {Direction::SW, 1, -1},
                                {Direction::W, 0, -1}, {Direction::NW, -1, -1}};

TEST(XnetShift, EveryDirectionAndDistanceMatchesTheTorusWrapAround) {
  // A non-square, non-power-of-two grid, so rows and columns cannot be confused.
  for (auto [rows, cols] : {std::pair{5, 7}, std::pair{8, 8}}) {
    MeshMachine m({rows, cols});
    std::vector<int> src(rows * cols);
    for (int pe = 0; pe < rows * cols; ++pe) src[pe] = 1000 + pe;
    Plural<int> a(m), b(m, -1);
    test::load(a, src);
    for (const auto& k : kCases)
      for (int d : {0, 1, 2, 3, rows, cols, cols + 1, 2 * rows + 3, 64}) {
        xnetShift(m, b, a, k.direction, d);
        EXPECT_TRUE(samePerPe(m.grid(), b, shiftedReference(rows, cols, src, k.dRow, k.dCol, d)))
            << rows << "x" << cols << " shift " << toString(k.direction) << " by " << d;
      }
  }
}

TEST(XnetShift, InPlaceShiftReadsTheOldValues) {
  MeshMachine m({4, 6});
  std::vector<int> src(24);
  for (int pe = 0; pe < 24; ++pe) src[pe] = pe * pe;
  Plural<int> a(m);
  test::load(a, src);
  xnetShift(m, a, a, Direction::SW, 5);
  EXPECT_TRUE(samePerPe(m.grid(), a, shiftedReference(4, 6, src, 1, -1, 5)));
}

TEST(XnetShift, OnlyActivePesReceive) {
  MeshMachine m({6, 6});
  Plural<int> a(m), b(m, -7);
  std::vector<int> src(36);
  for (int pe = 0; pe < 36; ++pe) src[pe] = pe;
  test::load(a, src);
  const Plural<bool> cond = test::randomCondition(m, 0.5, 11);
  auto expected = shiftedReference(6, 6, src, -1, 1, 2);
  for (int pe = 0; pe < 36; ++pe)
    if (!cond[pe]) expected[pe] = -7;
  {
    ActiveScope scope(m, cond);
    xnetShift(m, b, a, Direction::NE, 2);
  }
  EXPECT_TRUE(samePerPe(m.grid(), b, expected));
}

TEST(XnetShift, ListsMoveWholeAndCostTheLongestList) {
  MeshMachine m({4, 4});
  PeArray<int> src(m, "src"), dst(m, "dst");
  for (int pe = 0; pe < 16; ++pe)
    for (int i = 0; i < pe % 4; ++i) src.push(pe, 100 * pe + i);  // lengths 0..3
  xnetShift(m, dst, src, Direction::S, 1);
  for (int pe = 0; pe < 16; ++pe) {
    const int from = ((pe / 4 + 3) % 4) * 4 + pe % 4;  // the PE above, wrapping
    ASSERT_EQ(dst.count(pe), src.count(from)) << m.grid().name(pe);
    for (int i = 0; i < dst.count(pe); ++i) EXPECT_EQ(dst.at(pe, i), 100 * from + i);
  }
  EXPECT_EQ(m.costs().xnet.ops, 3);  // one shift per slot of the longest list
  EXPECT_EQ(m.costs().xnet.byteHops, 3 * static_cast<std::int64_t>(sizeof(int)));
}

TEST(XnetShift, ShiftEastBy3On8x8CostsExactlyTheModel) {
  MeshMachine m({8, 8});
  Plural<std::int32_t> a(m, 1), b(m);
  xnetShift(m, b, a, Direction::E, 3);
  const CostCounts c = m.costs();
  EXPECT_EQ(c.xnet.ops, 1);
  EXPECT_EQ(c.xnet.hops, 3);
  EXPECT_EQ(c.xnet.byteHops, 12);
  const Mp1Figures f;
  // 12 byte-hops over each PE's share of the 5.7 GB/s xnet: 8.62 microseconds.
  EXPECT_DOUBLE_EQ(emulatedSeconds(c).xnet, kTable11Calibration * 12.0 / (5.7e9 / 4096));
  EXPECT_NEAR(emulatedSeconds(c).total(), kTable11Calibration * 8.6232e-6, 1e-10);
  EXPECT_DOUBLE_EQ(emulatedSeconds(c).total(), emulatedSeconds(c).xnet);
}

TEST(XnetShift, RefusesNegativeDistance) {
  MeshMachine m({2, 2});
  Plural<int> a(m);
  EXPECT_THROW(xnetShift(m, a, a, Direction::E, -1), std::invalid_argument);
}

}  // namespace
}  // namespace radmesh::emu

namespace radmesh::emu {
namespace {

TEST(XnetShift, ListsShiftInPlace) {
  MeshMachine m({3, 5});
  PeArray<int> lists(m, "lists");
  for (int pe = 0; pe < 15; ++pe)
    for (int i = 0; i <= pe % 3; ++i) lists.push(pe, 10 * pe + i);
  xnetShift(m, lists, lists, Direction::NW, 4);
  for (int pe = 0; pe < 15; ++pe) {
    const int from = m.grid().index(m.grid().row(pe) + 4, m.grid().col(pe) + 4);
    ASSERT_EQ(lists.count(pe), from % 3 + 1) << m.grid().name(pe);
    for (int i = 0; i < lists.count(pe); ++i) EXPECT_EQ(lists.at(pe, i), 10 * from + i);
  }
}

TEST(XnetForward, StripsGrowByOnePePerStepAndKeepEverything) {
  // A record starting at row 0 of column c travels down c steps: after the spread, PE (r, c)
  // holds the records of column c whose strips reach row r.
  MeshMachine m({6, 4});
  PeArray<int> records(m, "records");
  PeArray<int> forward(m, "forward");
  for (int c = 0; c < 4; ++c) {
    records.push(c, 100 + c);
    if (c > 0) forward.push(c, 0);
  }
  for (int step = 1; step <= 3; ++step) {
    xnetForward(m, records, forward, Direction::S, 1);
    for (int pe = 0; pe < m.size(); ++pe)  // drop the records that have gone far enough
      if (forward.count(pe) > 0 && records.at(pe, forward.at(pe, 0)) - 100 <= step) forward.clear(pe);
  }
  for (int pe = 0; pe < m.size(); ++pe) {
    const int r = m.grid().row(pe), c = m.grid().col(pe);
    const int expected = r <= c ? 1 : 0;
    ASSERT_EQ(records.count(pe), expected) << m.grid().name(pe);
    if (expected) {
      EXPECT_EQ(records.at(pe, 0), 100 + c);
    }
  }
  EXPECT_EQ(m.costs().xnet.ops, 3);  // one shift per step: no PE forwards more than one record
  EXPECT_EQ(m.costs().xnet.byteHops, 3 * 4);
}

TEST(XnetForward, AnOverflowNamesThePeAndChangesNothing) {
  MeshMachine m({2, 2, /*memoryBudgetBytes=*/40});
  PeArray<std::int64_t> records(m, "records");
  PeArray<int> forward(m, "forward");
  for (int i = 0; i < 3; ++i) records.push(0, i), forward.push(0, i);  // 24 + 12 bytes
  records.push(1, 7);
  try {
    xnetForward(m, records, forward, Direction::E, 1);  // PE 1 would hold 4 records: 32 + 12
    FAIL() << "expected MemoryBudgetError";
  } catch (const MemoryBudgetError& e) {
    EXPECT_EQ(e.pe(), 1);
  }
  EXPECT_EQ(records.count(1), 1);
  EXPECT_EQ(forward.count(0), 3);
  EXPECT_EQ(forward.count(1), 0);
}

}  // namespace
}  // namespace radmesh::emu

namespace radmesh::emu {
namespace {

TEST(XnetShift, ListsReachOnlyActivePes) {
  MeshMachine m({4, 4});
  PeArray<int> lists(m, "lists");
  for (int pe = 0; pe < 16; ++pe) lists.push(pe, pe);
  const Plural<bool> cond = test::randomCondition(m, 0.5, 17);
  {
    ActiveScope scope(m, cond);
    xnetShift(m, lists, lists, Direction::E, 1);
  }
  for (int pe = 0; pe < 16; ++pe) {
    const int from = m.grid().index(m.grid().row(pe), m.grid().col(pe) - 1);
    ASSERT_EQ(lists.count(pe), 1);
    EXPECT_EQ(lists.at(pe, 0), cond[pe] ? from : pe) << m.grid().name(pe);
  }
}

}  // namespace
}  // namespace radmesh::emu
