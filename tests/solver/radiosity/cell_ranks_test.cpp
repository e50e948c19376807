#include "solver/radiosity/cell_ranks.h"

#include <gtest/gtest.h>

#include <span>
#include <stdexcept>

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

TEST(PortalMessage, DarkLinksSendNothing) {
  std::vector<double> runs;
  const std::vector<Rgb> dark(96, Rgb(0.0));
  EXPECT_EQ(appendPortalRuns(std::span(dark).first(48), 0, runs), 0u);
  EXPECT_EQ(appendPortalRuns(std::span(dark).last(48), 1, runs), 0u);
  const std::vector<double> message = portalMessage(runs, dark);
  EXPECT_TRUE(message.empty());
  EXPECT_EQ(readPortalMessage(message, 2, 48), dark);
}

// Two links of 6 bins: the first lit in bins 1-2 and 5, the second in all six: runs (1, 2), (5, 1)
// and (6 + 0, 6): 2 + 6 + 2 + 3 + 2 + 18 = 33 doubles, shorter than the 36 of the full bins.
TEST(PortalMessage, RunsOfLitBinsGoBackToTheirBins) {
  std::vector<Rgb> bins(12, Rgb(0.0));
  bins[1] = Rgb(1, 2, 3), bins[2] = Rgb(0, 0, 4), bins[5] = Rgb(5, 0, 0);
  for (int b = 6; b < 12; ++b) bins[b] = Rgb(b + 1.0, 0.5, 0.25);
  std::vector<double> runs;
  EXPECT_EQ(appendPortalRuns(std::span(bins).first(6), 0, runs), 2u + 6 + 2 + 3);
  EXPECT_EQ(appendPortalRuns(std::span(bins).last(6), 1, runs), 2u + 3 * 6);  // fully lit: 2 more than its bins
  EXPECT_EQ((std::vector<double>(runs.begin(), runs.begin() + 4)), (std::vector<double>{1, 2, 1, 2}));
  EXPECT_EQ(runs[13], 6.0);  // the second link's run starts at 1 x 6 + 0
  EXPECT_EQ(portalMessageDoubles(runs.size(), bins.size()), 33u);
  const std::vector<double> message = portalMessage(runs, bins);
  EXPECT_EQ(message, runs);
  EXPECT_EQ(readPortalMessage(message, 2, 6), bins);
}

// One link of one bin (diffuse portals), lit: its run (0, 1, r, g, b) is longer than the full bin.
TEST(PortalMessage, FullBinsWhereShorterThanTheRuns) {
  const std::vector<Rgb> bins{Rgb(0.5, 0.25, 0.125)};
  std::vector<double> runs;
  EXPECT_EQ(appendPortalRuns(bins, 0, runs), 5u);
  EXPECT_EQ(portalMessageDoubles(5, 1), 3u);
  const std::vector<double> message = portalMessage(runs, bins);
  EXPECT_EQ(message, (std::vector<double>{0.5, 0.25, 0.125}));
  EXPECT_EQ(readPortalMessage(message, 1, 1), bins);
}

TEST(PortalMessage, ARunOutsideTheLinksIsRefused) {
  std::vector<double> message;
  appendPortalRuns(std::vector<Rgb>(4, Rgb(1.0)), 1, message);  // bins 4-7: a second link
  EXPECT_THROW(readPortalMessage(message, 1, 4), std::runtime_error);
  message.pop_back();  // a run cut short
  EXPECT_THROW(readPortalMessage(message, 2, 4), std::runtime_error);
}

}  // namespace
}  // namespace radmesh
