#include "emulator/thread_pool.h"

#include <stdexcept>

namespace radmesh::emu {

namespace {
// Chunk c of [0, n) split into `parts`: sizes differ by at most one.
std::pair<int, int> chunk(int n, int parts, int c) {
  const long long begin = static_cast<long long>(n) * c / parts;
  const long long end = static_cast<long long>(n) * (c + 1) / parts;
  return {static_cast<int>(begin), static_cast<int>(end)};
}
}  // namespace

ThreadPool::ThreadPool(int threads) {
  if (threads < 1) throw std::invalid_argument("ThreadPool: needs at least one thread");
  errors_.resize(threads);
  for (int w = 1; w < threads; ++w) workers_.emplace_back([this, w] { workerLoop(w); });
}

ThreadPool::~ThreadPool() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (auto& t : workers_) t.join();
}

void ThreadPool::run(int n, const std::function<void(int, int)>& body) {
  const int parts = threads();
  if (parts == 1 || n < parts) {
    body(0, n);
    return;
  }
  {
    std::lock_guard lock(mutex_);
    n_ = n;
    body_ = &body;
    pending_ = parts - 1;
    for (auto& e : errors_) e = nullptr;
    ++generation_;
  }
  wake_.notify_all();
  const auto [begin, end] = chunk(n, parts, 0);
  try {
    body(begin, end);
  } catch (...) {
    errors_[0] = std::current_exception();
  }
  std::unique_lock lock(mutex_);
  done_.wait(lock, [this] { return pending_ == 0; });
  body_ = nullptr;
  for (auto& e : errors_)
    if (e) std::rethrow_exception(e);
}

void ThreadPool::workerLoop(int worker) {
  std::uint64_t seen = 0;
  for (;;) {
    std::unique_lock lock(mutex_);
    wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
    if (stopping_) return;
    seen = generation_;
    const auto* body = body_;
    const auto [begin, end] = chunk(n_, threads(), worker);
    lock.unlock();
    try {
      (*body)(begin, end);
    } catch (...) {
      errors_[worker] = std::current_exception();
    }
    lock.lock();
    if (--pending_ == 0) done_.notify_one();
  }
}

}  // namespace radmesh::emu
