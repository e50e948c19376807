#include "emulator/router.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "tests/emulator/plural_compare.h"

namespace radmesh::emu {
namespace {

using test::samePerPe;

struct Traffic {
  std::vector<int> value, destination;
  std::vector<bool> sends;
};

Traffic randomTraffic(int n, unsigned seed) {
  Traffic t;
  t.value = test::randomInts(n, -50, 50, seed);
  // Few destinations, so that many messages collide.
  t.destination = test::randomInts(n, 0, n / 8, seed + 1);
  const auto coin = test::randomInts(n, 0, 3, seed + 2);
  for (int c : coin) t.sends.push_back(c != 0);
  return t;
}

std::vector<int> combineReference(const Traffic& t, std::vector<int> dst, Combine mode) {
  for (std::size_t pe = 0; pe < t.value.size(); ++pe) {
    if (!t.sends[pe]) continue;
    int& to = dst[t.destination[pe]];
    const int m = t.value[pe];
    if (mode == Combine::Add) to += m;
    if (mode == Combine::Min) to = std::min(to, m);
    if (mode == Combine::Max) to = std::max(to, m);
    if (mode == Combine::Overwrite) to = m;  // later (higher) sources overwrite earlier ones
  }
  return dst;
}

TEST(RouterSend, EveryCombiningModeMatchesScalarAndCountsCollisionsExactly) {
  MeshMachine m({8, 8});
  const Traffic t = randomTraffic(64, 5);
  std::vector<int> arrivals(64, 0);
  int messages = 0;
  for (int pe = 0; pe < 64; ++pe)
    if (t.sends[pe]) ++arrivals[t.destination[pe]], ++messages;
  const int worst = *std::max_element(arrivals.begin(), arrivals.end());
  ASSERT_GT(worst, 2);  // the test needs real collisions

  const std::vector<int> initial = test::randomInts(64, -5, 5, 9);
  for (Combine mode : {Combine::Add, Combine::Min, Combine::Max, Combine::Overwrite}) {
    Plural<int> src(m), dst(m), to(m);
    Plural<bool> sends(m);
    test::load(src, t.value);
    test::load(to, t.destination);
    test::load(dst, initial);
    for (int pe = 0; pe < 64; ++pe) sends[pe] = t.sends[pe];
    RouterStats s;
    {
      ActiveScope scope(m, sends);
      s = routerSend(m, dst, src, to, mode);
    }
    EXPECT_TRUE(samePerPe(m.grid(), dst, combineReference(t, initial, mode)))
        << "mode " << static_cast<int>(mode);
    EXPECT_EQ(s.messages, messages);
    EXPECT_EQ(s.maxArrivals, worst);
    EXPECT_EQ(s.arrivals, arrivals);
  }
  EXPECT_EQ(m.costs().maxCollisions, worst);
}

TEST(RouterSend, OverwriteKeepsTheHighestSource) {
  MeshMachine m({4, 4});
  Plural<int> src(m), dst(m, -1), to(m, 5);  // all sixteen PEs send to PE 5
  for (int pe = 0; pe < 16; ++pe) src[pe] = 10 * pe;
  const RouterStats s = routerSend(m, dst, src, to, Combine::Overwrite);
  EXPECT_EQ(dst[5], 150);
  EXPECT_EQ(dst[4], -1);
  EXPECT_EQ(s.maxArrivals, 16);
}

TEST(RouterSend, RoundsAreTheBusiestClusterPort) {
  // 8 x 8 = four 4 x 4 clusters. A permutation within a cluster: 16 senders share the port.
  MeshMachine m({8, 8});
  Plural<int> v(m), identity(m);
  for (int pe = 0; pe < 64; ++pe) identity[pe] = pe;
  RouterStats s = routerSend(m, v, v, identity, Combine::Overwrite);
  EXPECT_EQ(s.rounds, 16);
  EXPECT_EQ(s.maxArrivals, 1);
  // One sender per cluster, all into PE 0: its port takes four messages in turn.
  Plural<bool> corner(m, false);
  for (int pe : {0, 4, 32, 36}) corner[pe] = true;
  Plural<int> zero(m, 0);
  {
    ActiveScope scope(m, corner);
    s = routerSend(m, v, v, zero, Combine::Add);
  }
  EXPECT_EQ(s.rounds, 4);
  EXPECT_EQ(s.maxArrivals, 4);
  const CostCounts c = m.costs();
  EXPECT_EQ(c.router.ops, 2);
  EXPECT_EQ(c.router.messages, 64 + 4);
  EXPECT_EQ(c.router.rounds, 16 + 4);
  EXPECT_EQ(c.router.byteRounds, (16 + 4) * static_cast<std::int64_t>(sizeof(int)));
}

TEST(RouterSendAppend, KeepsEveryMessageInSourceOrderAndCountsDepths) {
  MeshMachine m({8, 8});
  const Traffic t = randomTraffic(64, 21);
  Plural<int> src(m), to(m);
  Plural<bool> sends(m);
  test::load(src, t.value);
  test::load(to, t.destination);
  for (int pe = 0; pe < 64; ++pe) sends[pe] = t.sends[pe];
  PeArray<int> inbox(m, "inbox");
  inbox.push(3, 999);  // what was there stays first
  RouterStats s;
  {
    ActiveScope scope(m, sends);
    s = routerSendAppend(m, inbox, src, to);
  }
  std::vector<std::vector<int>> expected(64);
  expected[3].push_back(999);
  for (int pe = 0; pe < 64; ++pe)
    if (t.sends[pe]) expected[t.destination[pe]].push_back(t.value[pe]);
  for (int pe = 0; pe < 64; ++pe) {
    const auto got = inbox.list(pe);
    ASSERT_EQ(std::vector<int>(got.begin(), got.end()), expected[pe]) << m.grid().name(pe);
    EXPECT_EQ(s.arrivals[pe], static_cast<int>(expected[pe].size()) - (pe == 3 ? 1 : 0));
  }
}

TEST(RouterFetch, ReadsArbitraryPesAndCountsRequestsPerSource) {
  MeshMachine m({8, 8});
  const auto from = test::randomInts(64, 0, 9, 33);
  Plural<int> src(m), dst(m, -1), where(m);
  for (int pe = 0; pe < 64; ++pe) src[pe] = 7 * pe + 1;
  test::load(where, from);
  const Plural<bool> cond = test::randomCondition(m, 0.6, 34);
  RouterStats s;
  {
    ActiveScope scope(m, cond);
    s = routerFetch(m, dst, src, where);
  }
  std::vector<int> expected(64, -1), requests(64, 0);
  for (int pe = 0; pe < 64; ++pe)
    if (cond[pe]) expected[pe] = 7 * from[pe] + 1, ++requests[from[pe]];
  EXPECT_TRUE(samePerPe(m.grid(), dst, expected));
  EXPECT_EQ(s.maxArrivals, *std::max_element(requests.begin(), requests.end()));
  EXPECT_EQ(m.costs().router.rounds, 2 * s.rounds);  // request and reply passes
}

TEST(RouterSend, RefusesADestinationOutsideTheGridNamingTheSender) {
  MeshMachine m({4, 4});
  Plural<int> v(m), to(m, 0);
  to[6] = 16;
  try {
    routerSend(m, v, v, to, Combine::Add);
    FAIL() << "expected std::out_of_range";
  } catch (const std::out_of_range& e) {
    EXPECT_NE(std::string(e.what()).find("PE (row 1, col 2) addresses PE 16"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace radmesh::emu

namespace radmesh::emu {
namespace {

TEST(RouterSend, IntoLocalArrayElementsCombinesPerElement) {
  MeshMachine m({4, 4});
  PeArray<double> sums(m, 3, 0.0, "sums");
  Plural<double> v(m);
  Plural<int> pe(m), slot(m);
  for (int p = 0; p < 16; ++p) v[p] = p + 1.0, pe[p] = p % 2, slot[p] = p % 3;
  const RouterStats s = routerSend(m, sums, v, pe, slot, Combine::Add);
  double expected[2][3] = {};
  for (int p = 0; p < 16; ++p) expected[p % 2][p % 3] += p + 1.0;
  for (int to = 0; to < 2; ++to)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(sums.at(to, k), expected[to][k]) << "PE " << to << " slot " << k;
  EXPECT_EQ(s.maxArrivals, 8);
  slot[4] = 3;
  EXPECT_THROW(routerSend(m, sums, v, pe, slot, Combine::Add), std::out_of_range);
}

}  // namespace
}  // namespace radmesh::emu
