#pragma once
// Host threads for the native back end (--threads). Work is split into tasks whose boundaries
// never depend on the thread count, so results are bitwise the same for any number of threads.
#include <functional>
#include <memory>

namespace radmesh {

class ThreadPool {
 public:
  explicit ThreadPool(int threads);  // 0: one per hardware thread; 1: everything on the caller
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int size() const;  // workers, the calling thread included

  // Runs task(index, worker) for every index in [0, count) and returns when all are done. Which
  // worker (0 .. size()-1) runs which index varies from run to run; per-worker scratch is fine,
  // results that depend on the worker are not. The first exception a task throws is rethrown.
  void parallelFor(int count, const std::function<void(int index, int worker)>& task);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace radmesh
