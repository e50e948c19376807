#pragma once
// A mesh-connected SIMD machine: a toroidal grid of PEs with local memory, an active mask, host
// threads that run the PEs' local work, and the counts of what its programs did. Communication
// lives beside it (xnet.h, router.h, reduce.h, scan.h, mesh_sort.h); data in plural.h, pe_array.h.
// A process holds one block of the PEs (the whole torus unless a transport splits it over ranks,
// see transport.h): plural data are indexed by global PE id and store the block only.
#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <utility>

#include "emulator/active_mask.h"
#include "emulator/cost_counts.h"
#include "emulator/host_timer.h"
#include "emulator/memory_ledger.h"
#include "emulator/pe_block.h"
#include "emulator/pe_grid.h"
#include "emulator/transport.h"
#include "parallel/thread_pool.h"

namespace radmesh::emu {

struct MachineConfig {
  int rows = 64;  // the MP-1 of the paper: 64 x 64 = 4096 PEs (section 1.4)
  int cols = 64;
  std::int64_t memoryBudgetBytes = 16 * 1024;  // per PE, as the MP-1
  int threads = 1;  // host threads running PE work; results do not depend on it
  // The processes the torus is split over; none: this process holds all of it.
  std::shared_ptr<Transport> transport = nullptr;
};

// Local work a program declares per PE (SIMD: every PE steps through it, active or not).
struct AluCost {
  double flops = 0.0;
  double intOps = 0.0;
};

class MeshMachine {
 public:
  explicit MeshMachine(const MachineConfig& config = {});

  const PeGrid& grid() const { return grid_; }
  int size() const { return grid_.size(); }
  int threads() const { return pool_.size(); }

  // The PEs this process holds, and the map between their global ids and local (block) indices.
  bool distributed() const { return transport_ != nullptr; }
  Transport& transport() const { return *transport_; }  // only when distributed()
  const PeBlock& block() const { return block_; }
  int blockSize() const { return block_.size(); }
  bool holds(int pe) const { return !transport_ || block_.holds(grid_, pe); }
  int local(int pe) const { return transport_ ? block_.localIndex(grid_, pe) : pe; }
  int globalPe(int local) const { return transport_ ? block_.globalPe(grid_, local) : local; }
  int ownerOf(int pe) const;  // the rank holding pe (only when distributed())
  // The front end's walk over this process's PEs, in increasing global id (serial, not charged).
  template <class Visit>
  void forEachPe(Visit visit) const {
    for (int i = 0; i < blockSize(); ++i) visit(globalPe(i));
  }

  // SIMD `if`: narrow the active set, flip to the `else` branch, restore (see ActiveScope). The
  // mask covers this process's block; conditions are block-sized (Plural<bool>::values()).
  bool active(int pe) const { return mask_.active(local(pe)); }
  const ActiveMask& mask() const { return mask_; }
  void pushActive(std::span<const bool> condition) { mask_.push(condition); }
  void flipActive() { mask_.flip(); }
  void popActive() { mask_.pop(); }

  // Runs perPe(pe) on every active PE, over the host threads when the declared work is large
  // enough to pay for them, and charges `cost` to the ALU class.
  template <class PerPe>
  void compute(AluCost cost, PerPe&& perPe) {
    chargeAlu(cost);
    forEachActive(cost.flops + cost.intOps, std::forward<PerPe>(perPe));
  }
  // The same without charging, for a program that counts its SIMD steps as it goes (the most any
  // PE took) and charges them with chargeAlu afterwards; workPerPe guides the threading only.
  template <class PerPe>
  void forEachActive(double workPerPe, PerPe&& perPe);
  void chargeAlu(AluCost cost);  // declares local work

  MemoryLedger& memory() { return memory_; }
  const MemoryLedger& memory() const { return memory_; }

  CostCounts& counters() { return counts_; }  // for the operations that charge it
  CostCounts costs() const;                   // a snapshot, with the memory high-water mark
  void resetPeaks();  // restarts maxCollisions and the memory high-water mark from now

  bool inParallelRegion() const { return inParallel_.load(std::memory_order_relaxed); }

  // For an operation of class `c`: charges its host wall time to c.hostSeconds unless it runs
  // inside another timed operation.
  [[nodiscard]] HostTimer timeHost(ClassCounts& c) { return HostTimer(hostTimed_, c.hostSeconds); }

 private:
  // Declared operations x active PEs below which a compute() runs on the calling thread alone:
  // waking the pool costs about as much as this many simple host operations.
  static constexpr double kParallelMinWork = 20000.0;

  PeGrid grid_;
  std::shared_ptr<Transport> transport_;
  PeBlock block_;
  ActiveMask mask_;
  MemoryLedger memory_;
  ThreadPool pool_;
  CostCounts counts_;
  std::atomic<bool> inParallel_{false};
  bool hostTimed_ = false;  // a timeHost() timer is charging
};

// Operations take plural data of one machine only; throws std::invalid_argument otherwise.
void requireSameMachine(const MeshMachine& expected, const MeshMachine& got, const char* operation);

template <class PerPe>
void MeshMachine::forEachActive(double workPerPe, PerPe&& perPe) {
  const HostTimer timer = timeHost(counts_.alu);
  const std::uint8_t* flags = mask_.flags();
  const bool all = mask_.allActive();
  auto range = [&](int begin, int end) {
    for (int i = begin; i < end; ++i)
      if (all || flags[i]) perPe(globalPe(i));
  };
  const double work = workPerPe * mask_.activeCount();
  if (pool_.size() == 1 || work < kParallelMinWork) {
    range(0, blockSize());
    return;
  }
  inParallel_ = true;
  try {
    pool_.forEachChunk(blockSize(), range);
  } catch (...) {
    inParallel_ = false;
    throw;
  }
  inParallel_ = false;
}

}  // namespace radmesh::emu
