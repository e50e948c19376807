// The one host thread pool: every index or element exactly once, chunks fixed by n and the thread
// count alone, and the exception rethrown the one a single thread would have met first.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "parallel/thread_pool.h"

namespace radmesh {
namespace {

TEST(ThreadPool, SizeCountsTheCaller) {
  EXPECT_EQ(ThreadPool(1).size(), 1);
  EXPECT_EQ(ThreadPool(3).size(), 3);
  EXPECT_GE(ThreadPool(0).size(), 1);
  EXPECT_THROW(ThreadPool(-1), std::invalid_argument);
}

// The most threads worth asking for is what 0 asks for: the hardware threads, at least one.
TEST(ThreadPool, MostUsefulIsTheHardwareThreadsThatZeroGives) {
  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  EXPECT_EQ(ThreadPool::mostUseful(), hardware);
  EXPECT_EQ(ThreadPool::sizeFor(0), hardware);
  EXPECT_EQ(ThreadPool(0).size(), hardware);
  EXPECT_EQ(ThreadPool::sizeFor(hardware + 1), hardware + 1);  // a pool takes what it is given; the options cap
}

TEST(ThreadPool, ParallelForRunsEveryIndexOnceOnAKnownWorker) {
  ThreadPool pool(3);
  std::vector<std::atomic<int>> hit(1000);
  std::atomic<int> badWorker{0};
  pool.parallelFor(1000, [&](int index, int worker) {
    ++hit[index];
    if (worker < 0 || worker >= 3) ++badWorker;
  });
  EXPECT_EQ(std::count_if(hit.begin(), hit.end(), [](const std::atomic<int>& h) { return h == 1; }), 1000);
  EXPECT_EQ(badWorker, 0);
}

TEST(ThreadPool, ParallelForRethrowsTheLowestIndexsExceptionAndStaysUsable) {
  ThreadPool pool(2);
  for (int attempt = 0; attempt < 20; ++attempt) {
    try {
      pool.parallelFor(50, [](int index, int) {
        if (index % 7 == 3) throw std::runtime_error(std::to_string(index));
      });
      FAIL() << "expected an exception";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "3");
    }
  }
  int sum = 0;
  pool.parallelFor(1, [&](int index, int) { sum += index + 1; });
  EXPECT_EQ(sum, 1);
}

// The chunks [begin, end) a pool of `threads` makes of [0, n), in order.
std::vector<std::pair<int, int>> chunksOf(int threads, int n) {
  ThreadPool pool(threads);
  std::mutex mutex;
  std::vector<std::pair<int, int>> chunks;
  pool.forEachChunk(n, [&](int begin, int end) {
    std::lock_guard lock(mutex);
    chunks.emplace_back(begin, end);
  });
  std::sort(chunks.begin(), chunks.end());
  return chunks;
}

TEST(ThreadPool, ChunksAreContiguousAndFixedByTheCountAndThreads) {
  using Chunks = std::vector<std::pair<int, int>>;
  EXPECT_EQ(chunksOf(3, 10), (Chunks{{0, 3}, {3, 6}, {6, 10}}));
  EXPECT_EQ(chunksOf(4, 4096), (Chunks{{0, 1024}, {1024, 2048}, {2048, 3072}, {3072, 4096}}));
  EXPECT_EQ(chunksOf(1, 10), (Chunks{{0, 10}}));
  EXPECT_EQ(chunksOf(4, 3), (Chunks{{0, 3}}));  // fewer elements than threads: one chunk
  EXPECT_EQ(chunksOf(3, 10), chunksOf(3, 10));
}

TEST(ThreadPool, RethrowsTheLowestChunksExceptionAndStaysUsable) {
  ThreadPool pool(2);
  try {
    pool.forEachChunk(100, [](int begin, int) { throw std::runtime_error(std::to_string(begin)); });
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "0");
  }
  std::vector<int> hit(100, 0);
  pool.forEachChunk(100, [&](int begin, int end) {
    for (int i = begin; i < end; ++i) ++hit[i];
  });
  EXPECT_EQ(std::count(hit.begin(), hit.end(), 1), 100);
}

}  // namespace
}  // namespace radmesh
