#pragma once
// Segmented parallel-prefix sum (section 1.5's form-factor phase: sort, then scan, then send).
// Order: the active PEs in row-major order, and within a PE its list in order. A segment starts
// at every element whose start flag is set, and at the first active element. Inclusive: each
// element gets the sum of its segment up to and including itself; exclusive: up to but not
// including (T{} at a segment's start). Inactive PEs neither contribute nor receive.
// Distributed (transport.h): scan_across.h, by an ordered gather of the elements for floating
// point (bitwise the one-process sums), by exclusive scans of per-row summaries along the rank
// grid for integers (MPI_Exscan over MPI).
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "emulator/distributed.h"
#include "emulator/pe_array.h"
#include "emulator/plural.h"
#include "emulator/scan_across.h"
#include "emulator/segmented_sum.h"
#include "emulator/tree_cost.h"

namespace radmesh::emu {

namespace detail {
// A scan of `perPe` elements per PE: a local pass, the tree's two sweeps, a local fix-up.
template <class T>
void chargeScan(MeshMachine& machine, std::int64_t perPe) {
  ClassCounts& c = machine.counters().scan;
  detail::chargeTree(c, machine.grid(), 2, kWireBytes<T> + 1, std::is_floating_point_v<T>);
  (std::is_floating_point_v<T> ? c.flops : c.intOps) += 2.0 * static_cast<double>(perPe);
}
}  // namespace detail

template <class T>
void segmentedScan(MeshMachine& machine, Plural<T>& dst, const Plural<T>& src,
                   const Plural<bool>& segmentStart, ScanKind kind) {
  const HostTimer timer = machine.timeHost(machine.counters().scan);
  requireSameMachine(machine, dst.machine(), "segmentedScan");
  requireSameMachine(machine, src.machine(), "segmentedScan");
  requireSameMachine(machine, segmentStart.machine(), "segmentedScan");
  detail::chargeScan<T>(machine, 1);
  if (machine.distributed()) {
    std::vector<detail::ScanElement<T>> mine;
    for (int i = 0; i < machine.blockSize(); ++i)
      if (machine.mask().active(i)) {
        const int pe = machine.globalPe(i);
        mine.push_back({pe, src[pe], segmentStart[pe]});
      }
    const std::vector<T> results = detail::scanAcross(machine, mine, kind);
    for (std::size_t k = 0; k < mine.size(); ++k) dst[mine[k].pe] = results[k];
    return;
  }
  detail::SegmentedSum<T> sum(kind);
  for (int pe = 0; pe < machine.size(); ++pe)
    if (machine.active(pe)) dst[pe] = sum.next(src[pe], segmentStart[pe]);
}

// Lists: dst's list on each active PE takes src's length; segmentStart's lists must match src's.
template <class T>
void segmentedScan(MeshMachine& machine, PeArray<T>& dst, const PeArray<T>& src,
                   const PeArray<bool>& segmentStart, ScanKind kind) {
  const HostTimer timer = machine.timeHost(machine.counters().scan);
  requireSameMachine(machine, dst.machine(), "segmentedScan");
  requireSameMachine(machine, src.machine(), "segmentedScan");
  requireSameMachine(machine, segmentStart.machine(), "segmentedScan");
  detail::Problem mismatch;
  detail::MaxAt longest;
  for (int i = 0; i < machine.blockSize(); ++i) {
    if (!machine.mask().active(i)) continue;
    const int pe = machine.globalPe(i);
    if (segmentStart.count(pe) != src.count(pe)) mismatch.note(pe, segmentStart.count(pe), src.count(pe));
    if (src.count(pe) > longest.value) longest = {src.count(pe), pe};
  }
  mismatch = detail::firstProblem(machine, Channel::Scan, mismatch);
  if (mismatch.found())
    throw std::invalid_argument("segmentedScan: at " + machine.grid().name(mismatch.pe) + " '" +
                                segmentStart.label() + "' has " + std::to_string(mismatch.a) +
                                " flags for " + std::to_string(mismatch.b) + " values");
  longest = detail::allMaxAt(machine, Channel::Scan, longest);
  dst.reserve(static_cast<int>(longest.value), longest.pe);
  detail::chargeScan<T>(machine, longest.value);
  auto resize = [&](int pe) {  // dst's list takes src's length
    if (&dst == &src) return;
    dst.clear(pe);
    for (int i = 0; i < src.count(pe); ++i) dst.pushReserved(pe, T{});
  };
  if (machine.distributed()) {
    std::vector<detail::ScanElement<T>> mine;
    for (int i = 0; i < machine.blockSize(); ++i) {
      if (!machine.mask().active(i)) continue;
      const int pe = machine.globalPe(i);
      for (int k = 0; k < src.count(pe); ++k) mine.push_back({pe, src.at(pe, k), segmentStart.at(pe, k)});
    }
    const std::vector<T> results = detail::scanAcross(machine, mine, kind);
    std::size_t next = 0;
    for (int i = 0; i < machine.blockSize(); ++i) {
      if (!machine.mask().active(i)) continue;
      const int pe = machine.globalPe(i);
      resize(pe);
      for (int k = 0; k < src.count(pe); ++k) dst.at(pe, k) = results[next++];
    }
    return;
  }
  detail::SegmentedSum<T> sum(kind);
  for (int pe = 0; pe < machine.size(); ++pe) {
    if (!machine.active(pe)) continue;
    resize(pe);
    const int n = src.count(pe);
    for (int i = 0; i < n; ++i) dst.at(pe, i) = sum.next(src.at(pe, i), segmentStart.at(pe, i));
  }
}

}  // namespace radmesh::emu
