#pragma once
// The host threads the solver and the emulator share. Work is split into pieces whose boundaries
// depend on the count alone, never on which thread runs them, and the exception rethrown is the
// one of the lowest piece, the one a single thread would have met first: results and errors are
// bitwise the same for any number of threads.
#include <functional>
#include <memory>

namespace radmesh {

class ThreadPool {
 public:
  explicit ThreadPool(int threads);  // 0: one per hardware thread; 1: everything on the caller
  // The workers a pool of `threads` has: `threads`, or for 0 mostUseful().
  static int sizeFor(int threads);
  // The most host threads worth asking for: the hardware threads (at least one). More only wait for
  // a core, each holding its own scratch; --threads and the viewer's slider stop here.
  static int mostUseful();
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int size() const;  // workers, the calling thread included

  // Runs task(index, worker) for every index in [0, count) and returns when all are done. Indices
  // are handed out one at a time, so which worker (0 .. size()-1) runs which varies from run to
  // run; per-worker scratch is fine, results that depend on the worker are not. If tasks throw,
  // the lowest index's exception is rethrown.
  void parallelFor(int count, const std::function<void(int index, int worker)>& task);

  // Calls body(begin, end) on size() contiguous chunks of [0, n) whose sizes differ by at most
  // one (one chunk, on the caller, when n < size()), and waits for all. If chunks throw, the
  // lowest chunk's exception is rethrown.
  void forEachChunk(int n, const std::function<void(int begin, int end)>& body);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace radmesh
