// The mesh machine split over the MPI ranks (emulator/mpi) against the one-process machine on the
// same input: every operation's result, gathered to every rank, and its emulated cost counts equal.
#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <iostream>
#include <memory>
#include <numeric>
#include <random>
#include <vector>

#include "emulator/mesh_sort.h"
#include "emulator/mpi/mpi_transport.h"
#include "emulator/reduce.h"
#include "emulator/router.h"
#include "emulator/scan.h"
#include "emulator/xnet.h"

namespace radmesh::emu {
namespace {

// The same machine twice: whole in this process, and split in blocks over every rank.
struct Twin {
  MeshMachine one;
  MeshMachine split;
  Twin(int rows, int cols) : one({rows, cols}), split(distributed(rows, cols)) {}
  static MachineConfig distributed(int rows, int cols) {
    MachineConfig config{rows, cols};
    config.transport = std::make_shared<MpiTransport>();
    return config;
  }
};

std::vector<int> randomInts(int n, int lo, int hi, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> pick(lo, hi);
  std::vector<int> v(n);
  for (int& x : v) x = pick(rng);
  return v;
}
// Doubles over many magnitudes, so that a sum in another order has other bits.
std::vector<double> randomDoubles(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-20, 20);
  std::vector<double> v(n);
  for (double& x : v) x = std::ldexp(mantissa(rng), exponent(rng));
  return v;
}

// Sets the PEs this process holds from a whole-torus vector.
template <class T, class V>
void load(Plural<T>& p, const std::vector<V>& values) {
  for (int i = 0; i < p.blockSize(); ++i) {
    const int pe = p.machine().globalPe(i);
    p[pe] = static_cast<T>(values[pe]);
  }
}
template <class T>
void load(PeArray<T>& a, const std::vector<std::vector<T>>& lists) {
  for (int i = 0; i < a.machine().blockSize(); ++i) {
    const int pe = a.machine().globalPe(i);
    for (const T& x : lists[pe]) a.push(pe, x);
  }
}

template <class T>
struct Element {
  int pe;
  T value;
};
// The whole torus's values, gathered to every rank.
template <class T>
std::vector<T> whole(const Plural<T>& p) {
  MeshMachine& m = p.machine();
  if (!m.distributed()) return {p.data(), p.data() + p.size()};
  std::vector<Element<T>> mine;
  for (int i = 0; i < p.blockSize(); ++i) mine.push_back({m.globalPe(i), p.values()[i]});
  std::vector<T> all;
  for (const auto& e : detail::gatherByPe(m, Channel::Reduce, mine)) all.push_back(e.value);
  return all;
}
template <class T>
std::vector<std::vector<T>> whole(const PeArray<T>& a) {
  MeshMachine& m = a.machine();
  std::vector<Element<T>> mine;
  for (int i = 0; i < m.blockSize(); ++i)
    for (const T& x : a.list(m.globalPe(i))) mine.push_back({m.globalPe(i), x});
  if (m.distributed()) mine = detail::gatherByPe(m, Channel::Reduce, mine);
  std::vector<std::vector<T>> lists(m.size());
  for (const auto& e : mine) lists[e.pe].push_back(e.value);
  return lists;
}

// The emulated MP-1's counts, the host's time left out.
void expectSameCounts(const Twin& t) { EXPECT_EQ(t.split.costs().summary(), t.one.costs().summary()); }

void expectSameStats(const RouterStats& split, const RouterStats& one, const MeshMachine& m) {
  EXPECT_EQ(split.messages, one.messages);
  EXPECT_EQ(split.maxArrivals, one.maxArrivals);
  EXPECT_EQ(split.rounds, one.rounds);
  for (int i = 0; i < m.blockSize(); ++i) EXPECT_EQ(split.arrivals[m.globalPe(i)], one.arrivals[m.globalPe(i)]);
}

constexpr Direction kDirections[] = {Direction::N, Direction::NE, Direction::E, Direction::SE,
                                     Direction::S, Direction::SW, Direction::W, Direction::NW};

TEST(DistributedMesh, XnetShiftsInEveryDirectionAndDistanceWrapAround) {
  Twin t(16, 16);
  const auto input = randomInts(256, -1000, 1000, 1);
  const auto active = randomInts(256, 0, 1, 2);
  auto run = [&](MeshMachine& m) {
    Plural<int> src(m), dst(m, -7);
    Plural<bool> condition(m);
    load(src, input), load(condition, active);
    std::vector<std::vector<int>> results;
    for (Direction direction : kDirections)
      for (int distance : {0, 1, 5, 9, 19}) {
        xnetShift(m, dst, src, direction, distance);
        results.push_back(whole(dst));
        ActiveScope scope(m, condition);
        xnetShift(m, dst, dst, direction, distance);  // in place, half the PEs receiving
        results.push_back(whole(dst));
      }
    return results;
  };
  EXPECT_EQ(run(t.split), run(t.one));
  expectSameCounts(t);
}

TEST(DistributedMesh, ListShiftsAndForwardingMoveEveryItem) {
  Twin t(16, 16);
  const auto lengths = randomInts(256, 0, 3, 3);
  std::vector<std::vector<int>> lists(256);
  for (int pe = 0; pe < 256; ++pe)
    for (int k = 0; k < lengths[pe]; ++k) lists[pe].push_back(100 * pe + k);
  const auto active = randomInts(256, 0, 1, 4);
  // After the forward south, a PE holds its list and every other item of the one north of it.
  int longest = 0;
  for (int pe = 0; pe < 256; ++pe) longest = std::max(longest, lengths[pe] + (lengths[(pe + 256 - 16) % 256] + 1) / 2);
  auto run = [&](MeshMachine& m) {
    PeArray<int> src(m, "src"), dst(m, "dst"), records(m, "records"), forward(m, "forward");
    load(src, lists);
    load(records, lists);
    Plural<bool> condition(m);
    load(condition, active);
    xnetShift(m, dst, src, Direction::NE, 3);
    xnetShift(m, src, src, Direction::W, 9);
    {
      ActiveScope scope(m, condition);
      xnetShift(m, src, src, Direction::SE, 1);
    }
    for (int i = 0; i < m.blockSize(); ++i) {
      const int pe = m.globalPe(i);
      for (int k = 0; k < records.count(pe); k += 2) forward.push(pe, k);
    }
    xnetForward(m, records, forward, Direction::S, 1);
    EXPECT_EQ(records.maxCount(), longest);  // over every rank
    {
      ActiveScope scope(m, condition);
      xnetForward(m, records, forward, Direction::W, 17);
    }
    return std::vector{whole(src), whole(dst), whole(records), whole(forward)};
  };
  EXPECT_EQ(run(t.split), run(t.one));
  expectSameCounts(t);
}

TEST(DistributedMesh, RouterCombinesCollisionsInSourceOrder) {
  Twin t(16, 16);
  const auto value = randomDoubles(256, 5);
  const auto destination = randomInts(256, 0, 31, 6);  // 256 messages into 32 PEs: collisions
  const auto sends = randomInts(256, 0, 3, 7);
  const auto slot = randomInts(256, 0, 1, 8);
  auto run = [&](MeshMachine& m, std::vector<RouterStats>& stats) {
    Plural<double> src(m), dst(m, 1.0), fetched(m);
    Plural<int> to(m), toSlot(m);
    Plural<bool> sending(m);
    load(src, value), load(to, destination), load(toSlot, slot), load(sending, sends);
    PeArray<double> slots(m, 2, 0.5, "slots");
    PeArray<double> appended(m, "appended");
    std::vector<std::vector<double>> results;
    ActiveScope scope(m, sending);
    for (Combine combine : {Combine::Add, Combine::Min, Combine::Max, Combine::Overwrite}) {
      stats.push_back(routerSend(m, dst, src, to, combine));
      results.push_back(whole(dst));
    }
    stats.push_back(routerSend(m, slots, src, to, toSlot, Combine::Add));
    stats.push_back(routerSendAppend(m, appended, src, to));
    stats.push_back(routerFetch(m, fetched, src, to));
    results.push_back(whole(fetched));
    for (const auto& lists : {whole(slots), whole(appended)})
      for (const auto& list : lists) results.push_back(list);
    return results;
  };
  std::vector<RouterStats> one, split;
  EXPECT_EQ(run(t.split, split), run(t.one, one));
  ASSERT_EQ(split.size(), one.size());
  EXPECT_GT(one[0].maxArrivals, 4);  // the test needs real collisions
  for (std::size_t k = 0; k < one.size(); ++k) expectSameStats(split[k], one[k], t.split);
  expectSameCounts(t);
}

TEST(DistributedMesh, AnAddressOutsideTheGridIsRefusedOnEveryRank) {
  Twin t(16, 16);
  Plural<int> value(t.split, 1), to(t.split, 0);
  if (t.split.holds(77)) to[77] = 256;
  EXPECT_THROW(routerSend(t.split, value, value, to, Combine::Add), std::out_of_range);
}

TEST(DistributedMesh, ReductionsAndScansAreBitwiseTheOneProcessResults) {
  Twin t(16, 16);
  const auto doubles = randomDoubles(256, 9);
  const auto ints = randomInts(256, -1000, 1000, 10);
  const auto ties = randomInts(256, 0, 5, 11);
  const auto active = randomInts(256, 0, 2, 12);
  const auto starts = randomInts(256 * 3, 0, 4, 13);
  struct Results {
    double sum;
    int intSum;
    Located<double> best;
    Located<int> tie;
    std::vector<double> inclusive, exclusive;
    std::vector<std::vector<double>> lists;
    bool operator==(const Results& o) const {
      return sum == o.sum && intSum == o.intSum && best.value == o.best.value && best.pe == o.best.pe &&
             tie.value == o.tie.value && tie.pe == o.tie.pe && inclusive == o.inclusive &&
             exclusive == o.exclusive && lists == o.lists;
    }
  };
  auto run = [&](MeshMachine& m) {
    Plural<double> x(m), scanned(m, -1.0), exclusive(m, -1.0);
    Plural<int> n(m), tie(m);
    Plural<bool> condition(m), start(m);
    load(x, doubles), load(n, ints), load(tie, ties), load(condition, active);
    for (int i = 0; i < m.blockSize(); ++i) start[m.globalPe(i)] = starts[m.globalPe(i)] == 0;
    PeArray<double> values(m, "values"), sums(m, "sums");
    PeArray<bool> flags(m, "flags");
    for (int i = 0; i < m.blockSize(); ++i) {
      const int pe = m.globalPe(i);
      for (int k = 0; k < 3; ++k) values.push(pe, doubles[(pe * 3 + k) % 256] * (k + 1)), flags.push(pe, starts[pe * 3 + k] == 0);
    }
    Results r{};
    ActiveScope scope(m, condition);
    r.sum = reduceAdd(m, x);
    r.intSum = reduceAdd(m, n);
    r.best = reduceMax(m, x);
    r.tie = reduceMax(m, tie);  // many PEs hold the largest: the lowest wins
    segmentedScan(m, scanned, x, start, ScanKind::Inclusive);
    segmentedScan(m, exclusive, x, start, ScanKind::Exclusive);
    segmentedScan(m, sums, values, flags, ScanKind::Inclusive);
    r.inclusive = whole(scanned), r.exclusive = whole(exclusive), r.lists = whole(sums);
    return r;
  };
  const Results split = run(t.split), one = run(t.one);
  EXPECT_EQ(split.sum, one.sum);
  EXPECT_EQ(split.best.pe, one.best.pe);
  EXPECT_EQ(split.tie.pe, one.tie.pe);
  EXPECT_TRUE(split == one);
  expectSameCounts(t);
}

TEST(DistributedMesh, IntegerScansAreTheOneProcessResults) {
  Twin t(16, 16);
  const int n = 256;
  const auto ints = randomInts(n, -1000, 1000, 21);
  const auto wide = randomInts(n, 0, 1 << 20, 22);  // shifted by 20 bits: sums beyond an int
  const auto lengths = randomInts(n, 0, 3, 23);
  const auto active = randomInts(n, 0, 2, 24);
  const auto random = randomInts(n * 3, 0, 4, 25);
  // Where segments start (PE, slot): nowhere (one segment over every rank), at random, at the
  // first PE of every row, at every 8th column (where each block's piece of a row starts on 2 x 2
  // ranks), and at one PE inside a block only, its segment running through the later blocks.
  const std::vector<std::function<bool(int, int)>> patterns = {
      [](int, int) { return false; }, [&](int pe, int k) { return random[pe * 3 + k] == 0; },
      [](int pe, int k) { return pe % 16 == 0 && k == 0; }, [](int pe, int) { return pe % 8 == 0; },
      [](int pe, int) { return pe == 99; }};
  struct Results {
    std::vector<std::vector<int>> ints;
    std::vector<std::vector<std::int64_t>> wide;
    std::vector<std::vector<std::vector<int>>> lists;
    bool operator==(const Results&) const = default;
  };
  auto run = [&](MeshMachine& m) {
    Plural<bool> condition(m), everyone(m, true);
    load(condition, active);
    Results r;
    for (const auto& startsAt : patterns) {
      Plural<int> x(m);
      Plural<std::int64_t> w(m);
      Plural<bool> start(m);
      PeArray<int> values(m, "values");
      PeArray<bool> flags(m, "flags");
      load(x, ints);
      for (int i = 0; i < m.blockSize(); ++i) {
        const int pe = m.globalPe(i);
        w[pe] = std::int64_t{wide[pe]} << 20, start[pe] = startsAt(pe, 0);
        for (int k = 0; k < lengths[pe]; ++k) values.push(pe, ints[(pe * 3 + k) % n]), flags.push(pe, startsAt(pe, k));
      }
      for (const Plural<bool>* takesPart : {&everyone, &condition})
        for (ScanKind kind : {ScanKind::Inclusive, ScanKind::Exclusive}) {
          ActiveScope scope(m, *takesPart);
          Plural<int> y(m, -7);
          Plural<std::int64_t> z(m, -7);
          PeArray<int> sums(m, "sums");
          segmentedScan(m, y, x, start, kind);
          segmentedScan(m, z, w, start, kind);
          segmentedScan(m, sums, values, flags, kind);
          r.ints.push_back(whole(y)), r.wide.push_back(whole(z)), r.lists.push_back(whole(sums));
        }
    }
    return r;
  };
  const Results split = run(t.split), one = run(t.one);
  EXPECT_TRUE(split == one);
  // No starts, every PE taking part, inclusive: the last PE holds the sum of all.
  EXPECT_EQ(one.ints[0].back(), std::accumulate(ints.begin(), ints.end(), 0));
  EXPECT_GT(one.wide[0].back(), std::int64_t{1} << 32);
  expectSameCounts(t);
}

// An integer scan sends a summary per PE row of the block (an int sum and a flag) along the rank
// row twice (the exclusive scan to the later ranks, the rows' totals to all) and the block's total
// down the rank column to the later ranks: no element crosses, so the bytes do not grow with the
// PEs of other blocks.
TEST(DistributedMesh, AnIntegerScanSendsRowSummariesNotElements) {
  Twin t(64, 64);
  MeshMachine& m = t.split;
  Plural<int> x(m, 1), y(m);
  Plural<bool> start(m, false);
  Transport& transport = m.transport();
  transport.resetTraffic();
  segmentedScan(m, y, x, start, ScanKind::Inclusive);
  const RankGrid ranks = transport.rankGrid();
  const std::int64_t rows = 64 / ranks.rows, summary = sizeof(detail::RunSummary<int>);
  const int laterInRow = ranks.cols - 1 - transport.rankCol(), laterInColumn = ranks.rows - 1 - transport.rankRow();
  const Traffic sent = transport.traffic(Channel::Scan);
  EXPECT_EQ(summary, 8);
  EXPECT_EQ(sent.messages, laterInRow + (ranks.cols - 1) + laterInColumn);
  EXPECT_EQ(sent.bytes, (laterInRow + ranks.cols - 1) * rows * summary + laterInColumn * summary);
  m.forEachPe([&](int pe) { EXPECT_EQ(y[pe], pe + 1); });
}

TEST(DistributedMesh, SortIsTheOneProcessSortTiesIncluded) {
  Twin t(16, 16);
  const auto keys = randomInts(256 * 4, 0, 30, 14);  // many equal keys: the tie order shows
  const auto active = randomInts(256, 0, 3, 15);
  auto run = [&](MeshMachine& m) {
    PeArray<int> k(m, "keys"), v(m, "values");
    Plural<int> one(m), order(m);
    Plural<bool> condition(m);
    load(condition, active);
    for (int i = 0; i < m.blockSize(); ++i) {
      const int pe = m.globalPe(i);
      for (int s = 0; s < 4; ++s) k.push(pe, keys[pe * 4 + s]), v.push(pe, pe * 4 + s);
      one[pe] = keys[pe], order[pe] = pe;
    }
    sortPairs(m, k, v);
    {
      ActiveScope scope(m, condition);  // inactive PEs: the sorted pairs are placed on the active
      sortPairs(m, one, order);
    }
    return std::vector{whole(k), whole(v), std::vector{whole(one), whole(order)}};
  };
  EXPECT_EQ(run(t.split), run(t.one));
  expectSameCounts(t);
}

TEST(DistributedMesh, A128x128MachineSortsShiftsRoutesAndReduces) {
  Twin t(128, 128);
  const int n = 128 * 128;
  const auto keys = randomInts(n, 0, 5000, 16);
  const auto doubles = randomDoubles(n, 17);
  const auto destination = randomInts(n, 0, n - 1, 18);
  auto run = [&](MeshMachine& m) {
    Plural<int> k(m), v(m), to(m), shifted(m);
    Plural<double> x(m), received(m, 0.0);
    load(k, keys), load(x, doubles), load(to, destination);
    for (int i = 0; i < m.blockSize(); ++i) v[m.globalPe(i)] = m.globalPe(i);
    sortPairs(m, k, v);
    xnetShift(m, shifted, v, Direction::SE, 1);
    routerSend(m, received, x, to, Combine::Add);
    const double sum = reduceAdd(m, received);
    return std::tuple{whole(k), whole(shifted), whole(received), sum};
  };
  EXPECT_EQ(run(t.split), run(t.one));
  expectSameCounts(t);
}

TEST(DistributedMesh, AnEastShiftSendsOneEdgeBandToTheEastNeighbour) {
  Twin t(64, 64);
  Plural<int> x(t.split, 1), y(t.split);
  t.split.transport().resetTraffic();
  xnetShift(t.split, y, x, Direction::E, 1);
  const RankGrid ranks = t.split.transport().rankGrid();
  const int rows = 64 / ranks.rows;
  // Across a block edge: a size, then the band's counts and values (4 bytes each) per row.
  const Traffic sent = t.split.transport().traffic(Channel::Xnet);
  EXPECT_EQ(sent.messages, ranks.cols > 1 ? 2 : 0);
  EXPECT_EQ(sent.bytes, ranks.cols > 1 ? 8 + rows * (4 + 4) : 0);
}

// What each rank sends per operation on the MP-1's 64 x 64 (docs/scaling.md): run with
// RADMESH_MESH_TRAFFIC=1 to print it.
TEST(MeshTraffic, PerRankMessagesAndBytesOn64x64) {
  Twin t(64, 64);
  MeshMachine& m = t.split;
  Transport& transport = m.transport();
  const int n = 64 * 64;
  const auto keys = randomInts(n, 0, 1000, 19);
  const auto destination = randomInts(n, 0, n - 1, 20);
  Plural<int> k(m), v(m, 1), to(m), out(m);
  Plural<double> x(m, 0.5), y(m);
  Plural<bool> start(m, false);
  load(k, keys), load(to, destination);
  std::vector<std::pair<std::string, Traffic>> rows;
  auto measure = [&](const std::string& name, Channel channel, auto operation) {
    transport.resetTraffic();
    operation();
    rows.emplace_back(name, transport.traffic(channel));
  };
  measure("xnet E 1 (int)", Channel::Xnet, [&] { xnetShift(m, out, v, Direction::E, 1); });
  measure("xnet S 1 (int)", Channel::Xnet, [&] { xnetShift(m, out, v, Direction::S, 1); });
  measure("xnet SE 1 (int)", Channel::Xnet, [&] { xnetShift(m, out, v, Direction::SE, 1); });
  measure("router send (double, random)", Channel::Router, [&] { routerSend(m, y, x, to, Combine::Add); });
  measure("reduceMax (int)", Channel::Reduce, [&] { reduceMax(m, k); });
  measure("reduceAdd (int)", Channel::Reduce, [&] { reduceAdd(m, k); });
  measure("reduceAdd (double)", Channel::Reduce, [&] { reduceAdd(m, x); });
  measure("segmentedScan (int)", Channel::Scan, [&] { segmentedScan(m, out, v, start, ScanKind::Inclusive); });
  measure("segmentedScan (double)", Channel::Scan, [&] { segmentedScan(m, y, x, start, ScanKind::Inclusive); });
  measure("sortPairs (int, int)", Channel::Sort, [&] { sortPairs(m, k, v); });
  // An integer reduction is one MPI_Allreduce of the block's result to every peer.
  const int peers = transport.rankGrid().size() - 1;
  EXPECT_EQ(rows[4].second.messages, peers);
  EXPECT_EQ(rows[4].second.bytes, peers * static_cast<std::int64_t>(sizeof(Located<int>)));
  EXPECT_EQ(rows[5].second.messages, peers);
  EXPECT_EQ(rows[5].second.bytes, peers * static_cast<std::int64_t>(sizeof(int)));
  if (std::getenv("RADMESH_MESH_TRAFFIC"))
    for (const auto& [name, traffic] : rows)
      std::cout << "ranks " << transport.rankGrid().size() << " rank " << transport.rank() << " | " << name << " | "
                << traffic.messages << " | " << traffic.bytes << "\n";
}

}  // namespace
}  // namespace radmesh::emu
