#pragma once
// The sum a segmented scan runs (scan.h) over its elements in order, and the summary of a run of
// elements that a scan split over ranks (scan_across.h) carries from one run into the next.
namespace radmesh::emu {

enum class ScanKind { Inclusive, Exclusive };

namespace detail {
// From `carry`, the sum of the segment open before the first element (T{}: none); a segment
// starts at every element whose start flag is set.
template <class T>
class SegmentedSum {
 public:
  explicit SegmentedSum(ScanKind kind, T carry = T{}) : kind_(kind), running_(carry) {}
  T next(const T& value, bool segmentStart) {
    if (segmentStart) running_ = T{};
    const T before = running_;
    running_ = running_ + value;
    return kind_ == ScanKind::Inclusive ? running_ : before;
  }

 private:
  ScanKind kind_;
  T running_;
};

// A run of elements: the sum from its last segment start (from its first element if none), and
// whether a segment starts in it. Runs join in order, which regroups the additions: exact for
// integers only.
template <class T>
struct RunSummary {
  T sum{};
  bool starts = false;
};
template <class T>
RunSummary<T> join(const RunSummary<T>& earlier, const RunSummary<T>& later) {
  return later.starts ? later : RunSummary<T>{static_cast<T>(earlier.sum + later.sum), earlier.starts};
}
}  // namespace detail

}  // namespace radmesh::emu
