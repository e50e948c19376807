#pragma once
// Segmented parallel-prefix sum (section 1.5's form-factor phase: sort, then scan, then send).
// Order: the active PEs in row-major order, and within a PE its list in order. A segment starts
// at every element whose start flag is set, and at the first active element. Inclusive: each
// element gets the sum of its segment up to and including itself; exclusive: up to but not
// including (T{} at a segment's start). Inactive PEs neither contribute nor receive.
#include <stdexcept>
#include <type_traits>

#include "emulator/pe_array.h"
#include "emulator/plural.h"
#include "emulator/tree_cost.h"

namespace radmesh::emu {

enum class ScanKind { Inclusive, Exclusive };

namespace detail {
template <class T>
class SegmentedSum {
 public:
  explicit SegmentedSum(ScanKind kind) : kind_(kind) {}
  T next(const T& value, bool segmentStart) {
    if (segmentStart || !started_) running_ = T{};
    started_ = true;
    const T before = running_;
    running_ = running_ + value;
    return kind_ == ScanKind::Inclusive ? running_ : before;
  }

 private:
  ScanKind kind_;
  bool started_ = false;
  T running_{};
};

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
  int longest = 0;
  int longestAt = 0;
  for (int pe = 0; pe < machine.size(); ++pe) {
    if (!machine.active(pe)) continue;
    if (segmentStart.count(pe) != src.count(pe))
      throw std::invalid_argument("segmentedScan: at " + machine.grid().name(pe) + " '" +
                                  segmentStart.label() + "' has " +
                                  std::to_string(segmentStart.count(pe)) + " flags for " +
                                  std::to_string(src.count(pe)) + " values");
    if (src.count(pe) > longest) longest = src.count(pe), longestAt = pe;
  }
  dst.reserve(longest, longestAt);
  detail::chargeScan<T>(machine, longest);
  detail::SegmentedSum<T> sum(kind);
  for (int pe = 0; pe < machine.size(); ++pe) {
    if (!machine.active(pe)) continue;
    const int n = src.count(pe);
    if (&dst != &src) {
      dst.clear(pe);
      for (int i = 0; i < n; ++i) dst.pushReserved(pe, T{});
    }
    for (int i = 0; i < n; ++i) dst.at(pe, i) = sum.next(src.at(pe, i), segmentStart.at(pe, i));
  }
}

}  // namespace radmesh::emu
