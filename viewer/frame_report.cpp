#include "viewer/frame_report.h"

#include <fmt/format.h>

#include <algorithm>

namespace radmesh {

void FrameReport::add(double frameSeconds, double feedSeconds) {
  frames_.push_back(frameSeconds);
  feeds_.push_back(feedSeconds);
}

std::string FrameReport::summary() const {
  if (frames_.empty()) return {};
  std::vector<double> f = frames_, feed = feeds_;
  std::sort(f.begin(), f.end());
  std::sort(feed.begin(), feed.end());
  double sum = 0.0;
  for (double s : f) sum += s;
  const long slow = std::count_if(f.begin(), f.end(), [](double s) { return s > 1.0 / 30.0; });
  return fmt::format("{} frames with the mesh: lowest {:.1f} fps ({}), median {:.1f} fps ({}), mean {:.1f} fps, {} "
                     "under 30 fps; taking in snapshots: median {}, longest {} a frame",
                     f.size(), 1.0 / f.back(), frameTimeText(f.back()), 1.0 / f[f.size() / 2],
                     frameTimeText(f[f.size() / 2]), double(f.size()) / sum, slow, frameTimeText(feed[feed.size() / 2]),
                     frameTimeText(feed.back()));
}

std::string frameTimeText(double seconds) {
  return seconds >= 1e-4 ? fmt::format("{:.1f} ms", 1e3 * seconds) : fmt::format("{:.3g} µs", 1e6 * seconds);
}

}  // namespace radmesh
