#pragma once
// radmesh-view --frames N: each frame's time, and the part of it spent taking in the solver's
// snapshots, summed up in a line.
#include <string>
#include <vector>

namespace radmesh {

class FrameReport {
 public:
  void add(double frameSeconds, double feedSeconds);
  long frames() const { return static_cast<long>(frames_.size()); }
  // Lowest, median and mean frame rates, frames under 30 fps, and the snapshots' median and longest
  // times; empty before the first frame.
  std::string summary() const;

 private:
  std::vector<double> frames_, feeds_;
};

// A frame's time in ms to 0.1 ms, or below 0.1 ms in µs to three digits: taking in a snapshot
// often takes some µs, which "%.1f ms" said as "0.0 ms".
std::string frameTimeText(double seconds);

}  // namespace radmesh
