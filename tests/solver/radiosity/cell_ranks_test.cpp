#include "solver/radiosity/cell_ranks.h"

#include <gtest/gtest.h>

namespace radmesh {
namespace {

TEST(AssignCellsToRanks, RunsOfAboutEqualLoadInCellOrder) {
  // Loads 1..6 (21 in all) over 3 ranks: the midpoints 0.5, 2, 4.5, 8, 12.5, 18 of 21 fall in the
  // thirds 0, 0, 0, 1, 1, 2, so the runs carry 6, 9 and 6.
  EXPECT_EQ(assignCellsToRanks({1, 2, 3, 4, 5, 6}, 3), (std::vector<int>{0, 0, 0, 1, 1, 2}));
  EXPECT_EQ(assignCellsToRanks({1, 2, 3, 4, 5, 6}, 1), (std::vector<int>(6, 0)));
}

TEST(AssignCellsToRanks, MoreRanksThanCellsLeavesSomeEmpty) {
  EXPECT_EQ(assignCellsToRanks({5, 5}, 4), (std::vector<int>{1, 3}));
  EXPECT_EQ(assignCellsToRanks({0, 0, 0, 0}, 2), (std::vector<int>{0, 0, 1, 1}));  // no load: by count
}

TEST(AssignCellsToRanks, AHeavyCellGoesWhereItsMidpointFalls) {
  // The midpoint of the 100 is 52 of 104: exactly the second half's start.
  EXPECT_EQ(assignCellsToRanks({1, 1, 100, 1, 1}, 2), (std::vector<int>{0, 0, 1, 1, 1}));
}

}  // namespace
}  // namespace radmesh
