#pragma once
// Where the emulator's own time goes: the host wall time of a machine operation, charged to its
// operation class. Operations nest (a sort routes, a router call loops over PEs), so only the
// outermost timer of a nest charges and the classes add up to the time inside operations.
#include <chrono>

namespace radmesh::emu {

class HostTimer {
 public:
  // `running` is the machine's "a timer is charging" flag; `seconds` the class's host seconds.
  HostTimer(bool& running, double& seconds);
  ~HostTimer();
  HostTimer(const HostTimer&) = delete;
  HostTimer& operator=(const HostTimer&) = delete;

 private:
  bool* running_ = nullptr;  // null when nested inside another timer
  double* seconds_ = nullptr;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace radmesh::emu
