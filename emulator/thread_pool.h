#pragma once
// A persistent pool of host threads that runs one range of PEs per thread. The partition of
// [0, n) into contiguous chunks is fixed by n and the thread count alone, and each PE's work
// touches only that PE, so results never depend on scheduling.
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace radmesh::emu {

class ThreadPool {
 public:
  explicit ThreadPool(int threads);  // threads >= 1; the caller's thread is one of them
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int threads() const { return static_cast<int>(workers_.size()) + 1; }

  // Calls body(begin, end) on each chunk of [0, n) and waits for all. If chunks throw, the
  // exception of the lowest chunk is rethrown (the same one a single thread would have met first).
  void run(int n, const std::function<void(int begin, int end)>& body);

 private:
  void workerLoop(int worker);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  std::uint64_t generation_ = 0;
  int pending_ = 0;
  bool stopping_ = false;
  int n_ = 0;
  const std::function<void(int, int)>* body_ = nullptr;
  std::vector<std::exception_ptr> errors_;  // one slot per chunk
};

}  // namespace radmesh::emu
