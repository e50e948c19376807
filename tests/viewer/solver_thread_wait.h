#pragma once
// Waiting on the solver thread in tests. Every wait is bounded and fails the test when it runs
// out, so a broken build reports a hang instead of hanging the suite.
#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <future>
#include <memory>
#include <thread>

#include "viewer/solver_thread.h"

namespace radmesh::test {

using Snapshot = std::shared_ptr<const SolverSnapshot>;

// Polls until `ready` holds; fails the test after `limit` and returns the last snapshot.
inline Snapshot waitFor(const SolverThread& thread, const std::function<bool(const SolverSnapshot&)>& ready,
                        std::chrono::seconds limit = std::chrono::minutes(2)) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  for (;;) {
    Snapshot s = thread.latest();
    if (ready(*s)) return s;
    if (std::chrono::steady_clock::now() > deadline) {
      ADD_FAILURE() << "the solver thread did not get there within " << limit.count() << " s (iteration "
                    << s->iteration() << ", error '" << s->error << "')";
      return s;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

// Runs work on a thread of its own and says whether it finished within `limit`. A hung work is
// left behind (detached) so that the test can fail instead of hanging with it.
inline bool finishesWithin(std::chrono::seconds limit, std::function<void()> work) {
  auto finished = std::make_shared<std::promise<void>>();
  std::future<void> done = finished->get_future();
  std::thread([work = std::move(work), finished] {
    work();
    finished->set_value();
  }).detach();
  return done.wait_for(limit) == std::future_status::ready;
}

}  // namespace radmesh::test
