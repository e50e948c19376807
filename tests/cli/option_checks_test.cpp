// The option checks of cli/option_checks.h as units.
#include <gtest/gtest.h>

#include <string>

#include "cli/option_checks.h"
#include "parallel/thread_pool.h"

namespace radmesh::cli {
namespace {

int threadsGiven(const std::string& value) {
  CLI::App app;
  int threads = -1;
  app.add_option("--threads", threads)->transform(threadCount("radmesh"));
  app.parse("--threads " + value, false);
  return threads;
}

// --threads stops where the viewer's slider does, at ThreadPool::mostUseful(), with a warning.
TEST(OptionChecks, ThreadsAreCutToTheMostUseful) {
  const int most = ThreadPool::mostUseful();
  EXPECT_EQ(threadsGiven("0"), 0);
  EXPECT_EQ(threadsGiven(std::to_string(most)), most);
  testing::internal::CaptureStderr();
  EXPECT_EQ(threadsGiven(std::to_string(most + 1)), most);
  EXPECT_EQ(testing::internal::GetCapturedStderr(),
            "radmesh: warning: --threads " + std::to_string(most + 1) + " is more than the " + std::to_string(most) +
                " this machine runs at once: using " + std::to_string(most) + "\n");
}

}  // namespace
}  // namespace radmesh::cli
