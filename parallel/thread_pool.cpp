#include "parallel/thread_pool.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace radmesh {

struct ThreadPool::Impl {
  std::mutex mutex;
  std::condition_variable wake;
  std::condition_variable finished;
  const std::function<void(int, int)>* task = nullptr;
  int count = 0;
  std::atomic<int> next{0};
  long generation = 0;
  int busy = 0;  // helper threads still working on the current generation
  bool stopping = false;
  std::exception_ptr error;
  int errorIndex = 0;  // the index whose exception `error` holds: the lowest that threw
  std::vector<std::thread> helpers;

  // Tasks are handed out one index at a time; which worker takes which does not matter.
  void runTasks(int worker) {
    for (int index = next.fetch_add(1); index < count; index = next.fetch_add(1)) {
      try {
        (*task)(index, worker);
      } catch (...) {
        std::lock_guard lock(mutex);
        if (!error || index < errorIndex) {
          error = std::current_exception();
          errorIndex = index;
        }
      }
    }
  }

  void helperLoop(int worker) {
    long seen = 0;
    std::unique_lock lock(mutex);
    for (;;) {
      wake.wait(lock, [&] { return stopping || generation != seen; });
      if (stopping) return;
      seen = generation;
      lock.unlock();
      runTasks(worker);
      lock.lock();
      if (--busy == 0) finished.notify_one();
    }
  }
};

ThreadPool::ThreadPool(int threads) : impl_(std::make_unique<Impl>()) {
  if (threads < 0)
    throw std::invalid_argument("ThreadPool: " + std::to_string(threads) +
                                " threads is impossible; use 0 (one per hardware thread) or more");
  for (int worker = 1; worker < sizeFor(threads); ++worker)
    impl_->helpers.emplace_back([this, worker] { impl_->helperLoop(worker); });
}

int ThreadPool::sizeFor(int threads) { return threads > 0 ? threads : mostUseful(); }

int ThreadPool::mostUseful() { return static_cast<int>(std::max(1u, std::thread::hardware_concurrency())); }

ThreadPool::~ThreadPool() {
  {
    std::lock_guard lock(impl_->mutex);
    impl_->stopping = true;
  }
  impl_->wake.notify_all();
  for (std::thread& t : impl_->helpers) t.join();
}

int ThreadPool::size() const { return static_cast<int>(impl_->helpers.size()) + 1; }

void ThreadPool::parallelFor(int count, const std::function<void(int, int)>& task) {
  Impl& p = *impl_;
  if (p.helpers.empty() || count <= 1) {
    for (int index = 0; index < count; ++index) task(index, 0);
    return;
  }
  {
    std::lock_guard lock(p.mutex);
    p.task = &task;
    p.count = count;
    p.next = 0;
    p.error = nullptr;
    p.busy = static_cast<int>(p.helpers.size());
    ++p.generation;
  }
  p.wake.notify_all();
  p.runTasks(0);
  std::unique_lock lock(p.mutex);
  p.finished.wait(lock, [&] { return p.busy == 0; });
  p.task = nullptr;
  if (p.error) std::rethrow_exception(std::exchange(p.error, nullptr));
}

void ThreadPool::forEachChunk(int n, const std::function<void(int, int)>& body) {
  const int parts = size();
  if (parts == 1 || n < parts) {
    body(0, n);
    return;
  }
  parallelFor(parts, [&](int chunk, int) {
    const long long begin = static_cast<long long>(n) * chunk / parts;
    const long long end = static_cast<long long>(n) * (chunk + 1) / parts;
    body(static_cast<int>(begin), static_cast<int>(end));
  });
}

}  // namespace radmesh
