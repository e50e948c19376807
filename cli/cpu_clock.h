#pragma once
// CPU time of the calling thread. A one-thread solve runs wholly on it, so this times the work
// itself: other load on a shared machine stretches wall time by whatever the scheduler gives, not this.
#include <ctime>

namespace radmesh::cli {

inline double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

}  // namespace radmesh::cli
