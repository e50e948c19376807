#pragma once
// How the benchmarks time. A one-thread solve runs wholly on the calling thread, so its CPU time
// times the work itself: other load on a shared machine stretches wall time by whatever the
// scheduler gives, not this. Medians of per-iteration times are robust to the rest of the noise.
#include <algorithm>
#include <chrono>
#include <ctime>
#include <vector>

namespace radmesh::cli {

inline double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

inline double wallSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// One thread: the solve's own CPU time. More: wall time, the only clock that sees every thread.
inline double benchSeconds(int threads) { return threads == 1 ? threadCpuSeconds() : wallSeconds(); }

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace radmesh::cli
