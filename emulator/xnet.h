#pragma once
// xnet: every PE's direct links to its 8 neighbours on the torus (section 1.4). A shift moves a
// plural value `distance` hops in one direction, with wrap-around on all edges; the active PEs
// receive (each reads the PE `distance` hops behind it, active or not), inactive PEs keep their
// values. Cost: one operation of `distance` hops moving kWireBytes<T> bytes per PE per hop.
// Distributed (transport.h), a shift sends each block's edge band to the neighbouring rank along
// the columns, then along the rows (detail::shiftAcrossBlocks).
#include <algorithm>
#include <stdexcept>
#include <vector>

#include "emulator/distributed.h"
#include "emulator/pe_array.h"
#include "emulator/plural.h"

namespace radmesh::emu {

namespace detail {
void requireDistance(int distance, const char* operation);
// For every PE, the PE `distance` hops against `direction` (where a shift reads from). The
// table is the calling thread's scratch, valid until its next call.
const std::vector<int>& xnetSources(const PeGrid& grid, Direction direction, int distance);
void chargeXnet(MeshMachine& machine, std::int64_t items, int distance, std::int64_t itemBytes);

// What every block PE receives in a list shift, from `sent` (what each sent, by local index; host
// scratch, registers on the MP-1): one process reads it in place, where sourceOf(i) says; a
// distributed machine moves it across the block edges first.
template <class T>
class Arriving {
 public:
  Arriving(MeshMachine& machine, const SentLists<T>& sent, Direction direction, int distance) {
    if (machine.distributed()) {
      moved_ = shiftAcrossBlocks(machine, sent, direction, distance);
      lists_ = &moved_;
    } else {
      lists_ = &sent;
      from_ = &xnetSources(machine.grid(), direction, distance);
    }
  }
  int count(int i) const { return lists_->count(sourceOf(i)); }
  std::span<const T> list(int i) const {
    const int s = sourceOf(i);
    return {lists_->items.data() + lists_->begin[s], static_cast<std::size_t>(lists_->count(s))};
  }

 private:
  int sourceOf(int i) const { return from_ ? (*from_)[i] : i; }
  SentLists<T> moved_;
  const SentLists<T>* lists_ = nullptr;
  const std::vector<int>* from_ = nullptr;
};
}  // namespace detail

template <class T>
void xnetShift(MeshMachine& machine, Plural<T>& dst, const Plural<T>& src, Direction direction,
               int distance) {
  const HostTimer timer = machine.timeHost(machine.counters().xnet);
  requireSameMachine(machine, dst.machine(), "xnetShift");
  requireSameMachine(machine, src.machine(), "xnetShift");
  detail::requireDistance(distance, "xnetShift");
  detail::chargeXnet(machine, 1, distance, kWireBytes<T>);
  if (machine.distributed()) {
    auto& sent = detail::SentLists<T>::scratch();
    sent.items.assign(src.data(), src.data() + src.blockSize());
    sent.begin.resize(sent.items.size() + 1);
    for (std::size_t i = 0; i < sent.begin.size(); ++i) sent.begin[i] = static_cast<int>(i);
    const detail::Arriving<T> arriving(machine, sent, direction, distance);
    for (int i = 0; i < machine.blockSize(); ++i)
      if (machine.mask().active(i)) dst.data()[i] = arriving.list(i)[0];
    return;
  }
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
  auto& sent = detail::SentLists<T>::scratch();  // the lists as they were before the shift
  sent.reset(machine.blockSize());
  for (int i = 0; i < machine.blockSize(); ++i) {
    const auto list = src.list(machine.globalPe(i));
    sent.items.insert(sent.items.end(), list.begin(), list.end());
    sent.begin[i + 1] = static_cast<int>(sent.items.size());
  }
  const detail::Arriving<T> arriving(machine, sent, direction, distance);
  detail::MaxAt longest;
  for (int i = 0; i < machine.blockSize(); ++i)
    if (machine.mask().active(i) && arriving.count(i) > longest.value) longest = {arriving.count(i), machine.globalPe(i)};
  longest = detail::allMaxAt(machine, Channel::Xnet, longest);
  dst.reserve(static_cast<int>(longest.value), longest.pe);
  detail::chargeXnet(machine, longest.value, distance, kWireBytes<T>);
  for (int i = 0; i < machine.blockSize(); ++i) {
    if (!machine.mask().active(i)) continue;
    const int pe = machine.globalPe(i);
    dst.clear(pe);
    for (const T& item : arriving.list(i)) dst.pushReserved(pe, item);
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
  auto& sent = detail::SentLists<T>::scratch();
  sent.reset(machine.blockSize());
  for (int i = 0; i < machine.blockSize(); ++i) {
    const int pe = machine.globalPe(i);
    for (int index : forward.list(pe)) sent.items.push_back(records.at(pe, index));
    sent.begin[i + 1] = static_cast<int>(sent.items.size());
  }
  const detail::Arriving<T> arriving(machine, sent, direction, distance);
  struct Needs {
    std::int64_t sending = 0, longest = 0;  // the longest list sent, and received by an active PE
    detail::MaxAt need;                     // the longest records an active PE will hold
  } needs;
  for (int i = 0; i < machine.blockSize(); ++i) {
    needs.sending = std::max<std::int64_t>(needs.sending, sent.count(i));
    if (!machine.mask().active(i)) continue;
    const int incoming = arriving.count(i), pe = machine.globalPe(i);
    needs.longest = std::max<std::int64_t>(needs.longest, incoming);
    if (records.count(pe) + incoming > needs.need.value) needs.need = {records.count(pe) + incoming, pe};
  }
  if (machine.distributed())
    needs = detail::allReduce(machine, Channel::Xnet, needs, [](const Needs& in, Needs& inout) {
      inout.sending = std::max(inout.sending, in.sending);
      inout.longest = std::max(inout.longest, in.longest);
      if (in.need.value > inout.need.value || (in.need.value == inout.need.value && in.need.pe < inout.need.pe))
        inout.need = in.need;
    });
  records.reserve(static_cast<int>(needs.need.value), needs.need.pe);
  forward.reserve(static_cast<int>(needs.longest), needs.need.pe);
  detail::chargeXnet(machine, needs.sending, distance, kWireBytes<T>);
  for (int i = 0; i < machine.blockSize(); ++i) {
    if (!machine.mask().active(i)) continue;
    const int pe = machine.globalPe(i);
    forward.clear(pe);
    for (const T& item : arriving.list(i)) {
      forward.pushReserved(pe, records.count(pe));
      records.pushReserved(pe, item);
    }
  }
}

}  // namespace radmesh::emu
