#pragma once
// xnet: every PE's direct links to its 8 neighbours on the torus (section 1.4). A shift moves a
// plural value `distance` hops in one direction, with wrap-around on all edges; the active PEs
// receive (each reads the PE `distance` hops behind it, active or not), inactive PEs keep their
// values. Cost: one operation of `distance` hops moving kWireBytes<T> bytes per PE per hop.
#include <algorithm>
#include <stdexcept>
#include <vector>

#include "emulator/pe_array.h"
#include "emulator/plural.h"

namespace radmesh::emu {

namespace detail {
void requireDistance(int distance, const char* operation);
// For every PE, the PE `distance` hops against `direction` (where a shift reads from). The
// table is the calling thread's scratch, valid until its next call.
const std::vector<int>& xnetSources(const PeGrid& grid, Direction direction, int distance);

// What every PE sends in a list shift, gathered PE by PE (host scratch: registers on the MP-1).
template <class T>
struct SentLists {
  std::vector<T> items;
  std::vector<int> begin;  // PE pe's items are items[begin[pe] .. begin[pe + 1])
  void reset(int pes) {
    items.clear();
    begin.assign(pes + 1, 0);
  }
  static SentLists& scratch() {
    thread_local SentLists lists;
    return lists;
  }
};
void chargeXnet(MeshMachine& machine, std::int64_t items, int distance, std::int64_t itemBytes);
}  // namespace detail

template <class T>
void xnetShift(MeshMachine& machine, Plural<T>& dst, const Plural<T>& src, Direction direction,
               int distance) {
  const HostTimer timer = machine.timeHost(machine.counters().xnet);
  requireSameMachine(machine, dst.machine(), "xnetShift");
  requireSameMachine(machine, src.machine(), "xnetShift");
  detail::requireDistance(distance, "xnetShift");
  detail::chargeXnet(machine, 1, distance, kWireBytes<T>);
  const PeGrid& g = machine.grid();
  std::vector<T> aliased;
  const T* from = src.data();
  if (&dst == &src) {
    aliased.assign(src.data(), src.data() + src.size());
    from = aliased.data();
  }
  T* to = dst.data();
  const ActiveMask& mask = machine.mask();
  if (!mask.allActive()) {
    const std::vector<int>& source = detail::xnetSources(g, direction, distance);
    for (int pe = 0; pe < g.size(); ++pe)
      if (mask.active(pe)) to[pe] = from[source[pe]];
    return;
  }
  // Every PE receives: whole rows move, each rotated by the column offset (two block copies).
  const Step s = stepOf(direction);
  const long long dRow = static_cast<long long>(s.dRow) * distance % g.rows;
  const int shift = static_cast<int>(((static_cast<long long>(s.dCol) * distance) % g.cols + g.cols) % g.cols);
  for (int r = 0; r < g.rows; ++r) {
    const int sourceRow = static_cast<int>(((r - dRow) % g.rows + g.rows) % g.rows);
    const T* in = from + static_cast<std::size_t>(sourceRow) * g.cols;
    T* out = to + static_cast<std::size_t>(r) * g.cols;
    std::copy(in, in + (g.cols - shift), out + shift);
    std::copy(in + (g.cols - shift), in + g.cols, out);
  }
}

// Shifts whole per-PE lists: each active PE's list in dst becomes a copy of the list `distance`
// hops behind it (dst may be src: a shift in place). SIMD cost: as many shift operations as the
// longest list moved, each of kWireBytes<T> per PE.
template <class T>
void xnetShift(MeshMachine& machine, PeArray<T>& dst, const PeArray<T>& src, Direction direction,
               int distance) {
  const HostTimer timer = machine.timeHost(machine.counters().xnet);
  requireSameMachine(machine, dst.machine(), "xnetShift");
  requireSameMachine(machine, src.machine(), "xnetShift");
  detail::requireDistance(distance, "xnetShift");
  const std::vector<int>& from = detail::xnetSources(machine.grid(), direction, distance);
  int longest = 0;
  int longestAt = 0;
  for (int pe = 0; pe < machine.size(); ++pe)
    if (machine.active(pe) && src.count(from[pe]) > longest) longest = src.count(from[pe]), longestAt = pe;
  dst.reserve(longest, longestAt);
  detail::chargeXnet(machine, longest, distance, kWireBytes<T>);
  auto& sent = detail::SentLists<T>::scratch();  // the lists as they were before the shift
  sent.reset(machine.size());
  for (int pe = 0; pe < machine.size(); ++pe) {
    const auto list = src.list(pe);
    sent.items.insert(sent.items.end(), list.begin(), list.end());
    sent.begin[pe + 1] = static_cast<int>(sent.items.size());
  }
  for (int pe = 0; pe < machine.size(); ++pe) {
    if (!machine.active(pe)) continue;
    dst.clear(pe);
    for (int i = sent.begin[from[pe]]; i < sent.begin[from[pe] + 1]; ++i) dst.pushReserved(pe, sent.items[i]);
  }
}

// Spreading with accumulation: every PE sends the records that `forward` lists (indices into its
// `records`) `distance` hops toward `direction`; each active PE appends what reaches it to its own
// records, and its `forward` becomes the indices where they landed (the caller then drops those
// that need go no further). SIMD cost: as many shifts as the longest forward list, each of
// kWireBytes<T>. The records are reserved before anything changes, so a MemoryBudgetError (naming
// the PE that would overflow) leaves both arrays as they were.
template <class T>
void xnetForward(MeshMachine& machine, PeArray<T>& records, PeArray<int>& forward, Direction direction,
                 int distance) {
  const HostTimer timer = machine.timeHost(machine.counters().xnet);
  requireSameMachine(machine, records.machine(), "xnetForward");
  requireSameMachine(machine, forward.machine(), "xnetForward");
  detail::requireDistance(distance, "xnetForward");
  const std::vector<int>& from = detail::xnetSources(machine.grid(), direction, distance);
  int longest = 0, need = 0, needAt = 0, sending = 0;
  for (int pe = 0; pe < machine.size(); ++pe) {
    sending = std::max(sending, forward.count(pe));
    if (!machine.active(pe)) continue;
    const int incoming = forward.count(from[pe]);
    longest = std::max(longest, incoming);
    if (records.count(pe) + incoming > need) need = records.count(pe) + incoming, needAt = pe;
  }
  records.reserve(need, needAt);
  forward.reserve(longest, needAt);
  detail::chargeXnet(machine, sending, distance, kWireBytes<T>);
  auto& sent = detail::SentLists<T>::scratch();
  sent.reset(machine.size());
  for (int pe = 0; pe < machine.size(); ++pe) {
    for (int index : forward.list(pe)) sent.items.push_back(records.at(pe, index));
    sent.begin[pe + 1] = static_cast<int>(sent.items.size());
  }
  for (int pe = 0; pe < machine.size(); ++pe) {
    if (!machine.active(pe)) continue;
    forward.clear(pe);
    for (int i = sent.begin[from[pe]]; i < sent.begin[from[pe] + 1]; ++i) {
      forward.pushReserved(pe, records.count(pe));
      records.pushReserved(pe, sent.items[i]);
    }
  }
}

}  // namespace radmesh::emu
