// The MPI transport's combinations along a line of the rank grid keep the rank order: with a
// combination that is not commutative (writing digits after each other), every rank gets the
// digits of its line's ranks in order.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>

#include "emulator/distributed.h"
#include "emulator/mpi/mpi_transport.h"

namespace radmesh::emu {
namespace {

struct Digits {
  std::int64_t number = 0;
  std::int64_t width = 0;
};
void append(const Digits& earlier, Digits& later) {
  std::int64_t shift = 1;
  for (std::int64_t k = 0; k < later.width; ++k) shift *= 10;
  later = {earlier.number * shift + later.number, earlier.width + later.width};
}
// The digits first, first + 1, ... of `count` ranks.
std::int64_t digitsFrom(int first, int count) {
  std::int64_t number = 0;
  for (int k = 0; k < count; ++k) number = number * 10 + first + k;
  return number;
}

TEST(MpiTransport, CombinationsAlongARankLineKeepTheRankOrder) {
  MpiTransport transport;
  const RankGrid grid = transport.rankGrid();
  for (int axis : {0, 1}) {
    const int line = axis == 0 ? grid.rows : grid.cols;
    const int at = axis == 0 ? transport.rankRow() : transport.rankCol();
    // Two values, combined value by value: the ranks' digits from 1 and from 5.
    const std::array<Digits, 2> mine = {Digits{at + 1, 1}, Digits{at + 5, 1}};
    std::array<Digits, 2> all = mine, before = mine;
    transport.resetTraffic();
    transport.allReduceAlong(Channel::Scan, axis, std::as_writable_bytes(std::span(all)),
                             detail::combinerOf<Digits>(append, 2));
    const Traffic reduced = transport.traffic(Channel::Scan);
    transport.resetTraffic();
    const bool any = transport.exclusiveScanAlong(Channel::Scan, axis, std::as_writable_bytes(std::span(before)),
                                                  detail::combinerOf<Digits>(append, 2));
    const Traffic scanned = transport.traffic(Channel::Scan);
    EXPECT_EQ(all[0].number, digitsFrom(1, line)) << "axis " << axis;
    EXPECT_EQ(all[1].number, digitsFrom(5, line)) << "axis " << axis;
    EXPECT_EQ(any, at > 0);
    if (at > 0) {
      EXPECT_EQ(before[0].number, digitsFrom(1, at)) << "axis " << axis;
      EXPECT_EQ(before[1].number, digitsFrom(5, at)) << "axis " << axis;
    }
    // Every value goes to the line's other ranks, or in a scan to the ranks after this one.
    EXPECT_EQ(reduced.messages, line - 1);
    EXPECT_EQ(reduced.bytes, (line - 1) * static_cast<std::int64_t>(sizeof mine));
    EXPECT_EQ(scanned.messages, line - 1 - at);
    EXPECT_EQ(scanned.bytes, (line - 1 - at) * static_cast<std::int64_t>(sizeof mine));
  }
}

}  // namespace
}  // namespace radmesh::emu
