#include "cli/interrupt.h"

#include <fmt/core.h>

#include <atomic>
#include <csignal>

namespace radmesh::cli {
namespace {

std::atomic<bool> stopAsked{false};

extern "C" void askToStop(int signal) {
  if (stopAsked.exchange(true)) {  // the second time: at once
    std::signal(signal, SIG_DFL);
    std::raise(signal);
  }
}

}  // namespace

void stopSolvesOnInterrupt() {
  std::signal(SIGINT, askToStop);
  std::signal(SIGTERM, askToStop);
}

bool interrupted() { return stopAsked.load(); }

void stopAfterInterrupt(const std::string& where, const std::string& checkpointPath, const std::string& keepHint) {
  if (checkpointPath.empty())
    fmt::print(stderr, "radmesh: interrupted after {}: nothing saved ({})\n", where, keepHint);
  else
    fmt::print(stderr, "radmesh: interrupted after {}: the checkpoint {} holds the work; go on with --resume {}\n",
               where, checkpointPath, checkpointPath);
  throw Interrupted();
}

}  // namespace radmesh::cli
