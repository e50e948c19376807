#include "cli/interrupt.h"

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

}  // namespace radmesh::cli
