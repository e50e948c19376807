#pragma once
// A segmented scan (scan.h) over the ranks of a distributed machine (transport.h), in the
// one-process order: the active PEs in row-major order. A rank's 2-D block is not contiguous in
// that order, only its piece of each PE row is.
// - Floating point: a sum in another order has other bits, so every rank gathers the active
//   elements and runs the whole scan in order, keeping its block's results (docs/scaling.md).
// - Integers, exact in any grouping: each rank sums up its piece of every PE row (RunSummary);
//   what comes before the piece in its row is an exclusive scan of those along the rank row, the
//   rows' totals an ordered all-reduce along it, and the rank rows above an exclusive scan of the
//   block's total down the rank column: a few bytes per PE row instead of every element.
#include <span>
#include <type_traits>
#include <vector>

#include "emulator/distributed.h"
#include "emulator/segmented_sum.h"

namespace radmesh::emu::detail {

template <class T>
struct ScanElement {
  int pe = 0;
  T value{};
  bool start = false;
};

template <class T>
std::vector<T> scanByGather(MeshMachine& machine, const std::vector<ScanElement<T>>& mine, ScanKind kind) {
  SegmentedSum<T> sum(kind);
  std::vector<T> results;
  results.reserve(mine.size());
  for (const ScanElement<T>& e : gatherByPe(machine, Channel::Scan, mine)) {
    const T result = sum.next(e.value, e.start);
    if (machine.holds(e.pe)) results.push_back(result);
  }
  return results;
}

template <class T>
std::vector<T> scanByRowSummaries(MeshMachine& machine, const std::vector<ScanElement<T>>& mine, ScanKind kind) {
  const PeBlock& block = machine.block();
  auto rowOf = [&](const ScanElement<T>& e) { return machine.grid().row(e.pe) - block.firstRow; };
  std::vector<RunSummary<T>> pieces(block.rows);
  for (const ScanElement<T>& e : mine) pieces[rowOf(e)] = join(pieces[rowOf(e)], RunSummary<T>{e.value, e.start});
  auto joinInto = [](const RunSummary<T>& earlier, RunSummary<T>& later) { later = join(earlier, later); };
  std::vector<RunSummary<T>> before = pieces, rows = pieces;
  exclusiveScanAlong(machine, Channel::Scan, 1, std::span(before), joinInto, RunSummary<T>{});
  allReduceAlong(machine, Channel::Scan, 1, std::span(rows), joinInto);
  RunSummary<T> above;  // the block's total, scanned down the rank column: the rank rows above
  for (const RunSummary<T>& row : rows) above = join(above, row);
  exclusiveScanAlong(machine, Channel::Scan, 0, std::span(&above, 1), joinInto, RunSummary<T>{});
  // Each PE row: what is above it, then the pieces before this block's in the row.
  std::vector<T> results;
  results.reserve(mine.size());
  std::size_t k = 0;
  for (int r = 0; r < block.rows; ++r) {
    SegmentedSum<T> sum(kind, join(above, before[r]).sum);
    for (; k < mine.size() && rowOf(mine[k]) == r; ++k) results.push_back(sum.next(mine[k].value, mine[k].start));
    above = join(above, rows[r]);
  }
  return results;
}

// The scan of every rank's elements (each block's in its order); returns the results of this
// block's elements, in its order.
template <class T>
std::vector<T> scanAcross(MeshMachine& machine, const std::vector<ScanElement<T>>& mine, ScanKind kind) {
  if constexpr (std::is_integral_v<T>)
    return scanByRowSummaries(machine, mine, kind);
  else
    return scanByGather(machine, mine, kind);
}

}  // namespace radmesh::emu::detail
