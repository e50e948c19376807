#pragma once
// The pieces the operations share when the machine is split over processes (transport.h): values
// combined over ranks (all of them, or in order along a rank row or column), an error every rank
// agrees on, per-PE lists moved across block edges, router messages delivered to the blocks that
// hold their destinations, and records gathered in global PE order. Everything moved must be
// trivially copyable (it travels as bytes).
#include <algorithm>
#include <cstring>
#include <limits>
#include <span>
#include <type_traits>
#include <vector>

#include "emulator/mesh_machine.h"

namespace radmesh::emu::detail {

template <class T>
Bytes toBytes(std::span<const T> values) {
  static_assert(std::is_trivially_copyable_v<T>, "distributed data travel as bytes");
  Bytes out(values.size_bytes());
  if (!values.empty()) std::memcpy(out.data(), values.data(), out.size());
  return out;
}
template <class T>
std::vector<T> fromBytes(std::span<const std::byte> bytes) {
  std::vector<T> out(bytes.size() / sizeof(T));
  if (!out.empty()) std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
  return out;
}

// combine(in, inout) of values of T as the transport's, on the bytes of `count` values, value by value.
template <class T, class Combine>
Transport::Combiner combinerOf(Combine combine, std::size_t count = 1) {
  static_assert(std::is_trivially_copyable_v<T>, "distributed data travel as bytes");
  return [combine, count](const std::byte* in, std::byte* inout) {
    for (std::size_t k = 0; k < count; ++k) {
      T a, b;
      std::memcpy(&a, in + k * sizeof(T), sizeof(T));
      std::memcpy(&b, inout + k * sizeof(T), sizeof(T));
      combine(a, b);
      std::memcpy(inout + k * sizeof(T), &b, sizeof(T));
    }
  };
}

// value combined over every rank; combine(in, inout) must be commutative and associative.
template <class T, class Combine>
T allReduce(MeshMachine& machine, Channel channel, T value, Combine combine) {
  machine.transport().allReduce(channel, std::as_writable_bytes(std::span(&value, 1)), combinerOf<T>(combine));
  return value;
}
// Along a line of the rank grid (`axis` as Transport's), value by value, with combine(earlier,
// later) associative: each of `values` becomes the combination of the line's in order.
template <class T, class Combine>
void allReduceAlong(MeshMachine& machine, Channel channel, int axis, std::span<T> values, Combine combine) {
  machine.transport().allReduceAlong(channel, axis, std::as_writable_bytes(values),
                                     combinerOf<T>(combine, values.size()));
}
// ... or of the ranks' before this one, `identity` on the line's first rank.
template <class T, class Combine>
void exclusiveScanAlong(MeshMachine& machine, Channel channel, int axis, std::span<T> values, Combine combine,
                        const T& identity) {
  if (!machine.transport().exclusiveScanAlong(channel, axis, std::as_writable_bytes(values),
                                              combinerOf<T>(combine, values.size())))
    std::fill(values.begin(), values.end(), identity);
}
template <class T>
T allSum(MeshMachine& machine, Channel channel, T value) {
  return allReduce(machine, channel, value, [](const T& in, T& inout) { inout = inout + in; });
}

// The largest value over the ranks and the lowest PE that has it (the one a serial scan names).
struct MaxAt {
  std::int64_t value = 0;
  int pe = 0;
};
inline MaxAt allMaxAt(MeshMachine& machine, Channel channel, MaxAt mine) {
  if (!machine.distributed()) return mine;
  return allReduce(machine, channel, mine, [](const MaxAt& in, MaxAt& inout) {
    if (in.value > inout.value || (in.value == inout.value && in.pe < inout.pe)) inout = in;
  });
}

// A problem a PE found (the lowest PE wins, as in a serial scan) with numbers for the message:
// every rank learns the same one, so that all throw alike instead of some waiting for the others.
struct Problem {
  int pe = std::numeric_limits<int>::max();
  std::int64_t a = 0;
  std::int64_t b = 0;
  std::int64_t c = 0;
  bool found() const { return pe != std::numeric_limits<int>::max(); }
  void note(int at, std::int64_t first, std::int64_t second = 0, std::int64_t third = 0) {
    if (at < pe) pe = at, a = first, b = second, c = third;
  }
};
inline Problem firstProblem(MeshMachine& machine, Channel channel, Problem mine) {
  if (!machine.distributed()) return mine;
  return allReduce(machine, channel, mine, [](const Problem& in, Problem& inout) {
    if (in.pe < inout.pe) inout = in;
  });
}

// Per-PE lists of the block, by local index: PE i's items are items[begin[i] .. begin[i + 1]).
template <class T>
struct SentLists {
  std::vector<T> items;
  std::vector<int> begin;
  void reset(int pes) {
    items.clear();
    begin.assign(pes + 1, 0);
  }
  int count(int i) const { return begin[i + 1] - begin[i]; }
  static SentLists& scratch() {
    thread_local SentLists lists;
    return lists;
  }
};

// The block PEs whose coordinate along `axis` (0: row, 1: col) lies in [lo, hi), in local order.
template <class Visit>
void forEachInBand(const PeBlock& block, int axis, int lo, int hi, Visit visit) {
  for (int r = 0; r < block.rows; ++r)
    for (int c = 0; c < block.cols; ++c) {
      const int at = axis == 0 ? r : c;
      if (at >= lo && at < hi) visit(r * block.cols + c);
    }
}

// Moves every list `amount` PEs along `axis` of the torus: the band that stays in a block goes to
// the rank amount / extent blocks on, the band that spills over the edge to the one after it.
template <class T>
SentLists<T> shiftAlong(MeshMachine& machine, Channel channel, const SentLists<T>& lists, int axis,
                        int amount) {
  const PeBlock& b = machine.block();
  const int extent = axis == 0 ? b.rows : b.cols;
  const int gridExtent = axis == 0 ? machine.grid().rows : machine.grid().cols;
  amount = ((amount % gridExtent) + gridExtent) % gridExtent;
  const int blocks = amount / extent, rest = amount % extent;
  std::vector<int> counts(b.size(), 0);
  std::vector<Bytes> received;
  std::vector<std::pair<int, int>> landing;  // the band each received packet fills
  auto send = [&](int lo, int hi, int displacement, int landLo) {
    if (lo == hi) return;
    std::vector<int> header;
    std::vector<T> items;
    forEachInBand(b, axis, lo, hi, [&](int i) {
      header.push_back(lists.count(i));
      items.insert(items.end(), lists.items.begin() + lists.begin[i], lists.items.begin() + lists.begin[i + 1]);
    });
    Bytes packet = toBytes(std::span<const int>(header));
    const Bytes body = toBytes(std::span<const T>(items));
    packet.insert(packet.end(), body.begin(), body.end());
    received.push_back(machine.transport().shift(channel, axis, displacement, packet));
    landing.emplace_back(landLo, landLo + (hi - lo));
  };
  send(0, extent - rest, blocks, rest);
  send(extent - rest, extent, blocks + 1, 0);
  // Unpack: counts first, then the items in local order.
  std::vector<std::pair<const std::byte*, int>> source(b.size());  // each PE's items and count
  for (std::size_t p = 0; p < received.size(); ++p) {
    const std::byte* at = received[p].data();
    std::vector<int> band;
    forEachInBand(b, axis, landing[p].first, landing[p].second, [&](int i) { band.push_back(i); });
    const std::byte* items = at + band.size() * sizeof(int);
    for (std::size_t k = 0; k < band.size(); ++k) {
      int n;
      std::memcpy(&n, at + k * sizeof(int), sizeof(int));
      source[band[k]] = {items, n};
      items += static_cast<std::size_t>(n) * sizeof(T);
    }
  }
  SentLists<T> out;
  out.reset(b.size());
  for (int i = 0; i < b.size(); ++i) {
    const std::vector<T> list = fromBytes<T>({source[i].first, source[i].second * sizeof(T)});
    out.items.insert(out.items.end(), list.begin(), list.end());
    out.begin[i + 1] = static_cast<int>(out.items.size());
  }
  return out;
}

// Every block PE's list as the PE `distance` hops against `direction` had it: the columns move
// first, then the rows (a diagonal step crosses two edges, as on the MP-1's X-net).
template <class T>
SentLists<T> shiftAcrossBlocks(MeshMachine& machine, const SentLists<T>& lists, Direction direction,
                               int distance) {
  const Step s = stepOf(direction);
  const long long cols = static_cast<long long>(s.dCol) * distance % machine.grid().cols;
  const long long rows = static_cast<long long>(s.dRow) * distance % machine.grid().rows;
  const SentLists<T> across = shiftAlong(machine, Channel::Xnet, lists, 1, static_cast<int>(cols));
  return shiftAlong(machine, Channel::Xnet, across, 0, static_cast<int>(rows));
}

// Sends every message to the rank holding its destination PE (`to`) and returns those for this
// block in increasing source order (`from`; a source's messages keep their order).
template <class M>
std::vector<M> deliver(MeshMachine& machine, Channel channel, const std::vector<M>& outgoing) {
  std::vector<std::vector<M>> perRank(machine.transport().rankGrid().size());
  for (const M& m : outgoing) perRank[machine.ownerOf(m.to)].push_back(m);
  std::vector<Bytes> toRank;
  for (const auto& messages : perRank) toRank.push_back(toBytes(std::span<const M>(messages)));
  std::vector<M> arrived;
  for (const Bytes& bytes : machine.transport().allToAll(channel, toRank)) {
    const std::vector<M> part = fromBytes<M>(bytes);
    arrived.insert(arrived.end(), part.begin(), part.end());
  }
  std::stable_sort(arrived.begin(), arrived.end(), [](const M& a, const M& b) { return a.from < b.from; });
  return arrived;
}

// Every rank's records, in increasing PE order (`pe`; a PE's records keep their order).
template <class R>
std::vector<R> gatherByPe(MeshMachine& machine, Channel channel, const std::vector<R>& mine) {
  std::vector<R> all;
  for (const Bytes& bytes : machine.transport().allGather(channel, toBytes(std::span<const R>(mine)))) {
    const std::vector<R> part = fromBytes<R>(bytes);
    all.insert(all.end(), part.begin(), part.end());
  }
  std::stable_sort(all.begin(), all.end(), [](const R& a, const R& b) { return a.pe < b.pe; });
  return all;
}

}  // namespace radmesh::emu::detail
