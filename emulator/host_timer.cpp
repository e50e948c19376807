#include "emulator/host_timer.h"

namespace radmesh::emu {

HostTimer::HostTimer(bool& running, double& seconds) {
  if (running) return;
  running = true;
  running_ = &running;
  seconds_ = &seconds;
  start_ = std::chrono::steady_clock::now();
}

HostTimer::~HostTimer() {
  if (!running_) return;
  *seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  *running_ = false;
}

}  // namespace radmesh::emu
