#include "emulator/mesh_machine.h"

#include <stdexcept>
#include <string>

namespace radmesh::emu {

namespace {
MachineConfig checked(const MachineConfig& c) {
  if (c.rows < 1 || c.cols < 1 || static_cast<std::int64_t>(c.rows) * c.cols > (1 << 24))
    throw std::invalid_argument("MeshMachine: a grid of " + std::to_string(c.rows) + " x " +
                                std::to_string(c.cols) +
                                " PEs is impossible; use 1..16M PEs (the MP-1 has 1024..16384)");
  if (c.memoryBudgetBytes < 1)
    throw std::invalid_argument("MeshMachine: the per-PE memory budget must be positive");
  if (c.threads < 1)
    throw std::invalid_argument("MeshMachine: needs at least one host thread, got " +
                                std::to_string(c.threads));
  return c;
}

PeBlock blockOfThisProcess(const PeGrid& grid, const Transport* transport) {
  if (!transport) return {0, 0, grid.rows, grid.cols};
  return blockOf(grid, transport->rankGrid(), transport->rankRow(), transport->rankCol());
}
}  // namespace

MeshMachine::MeshMachine(const MachineConfig& config)
    : grid_{checked(config).rows, config.cols},
      transport_(config.transport),
      block_(blockOfThisProcess(grid_, transport_.get())),
      mask_(block_.size()),
      memory_(grid_, config.memoryBudgetBytes),
      pool_(config.threads) {}

void requireSameMachine(const MeshMachine& expected, const MeshMachine& got, const char* operation) {
  if (&expected != &got)
    throw std::invalid_argument(std::string(operation) +
                                ": its plural data belong to different machines");
}

int MeshMachine::ownerOf(int pe) const {
  return transport_->rankAt(grid_.row(pe) / block_.rows, grid_.col(pe) / block_.cols);
}

void MeshMachine::chargeAlu(AluCost cost) {
  counts_.alu.ops += 1;
  counts_.alu.flops += cost.flops;
  counts_.alu.intOps += cost.intOps;
}

CostCounts MeshMachine::costs() const {
  CostCounts c = counts_;
  c.memoryHighWaterBytes = memory_.highWaterBytes();
  return c;
}

void MeshMachine::resetPeaks() {
  counts_.maxCollisions = 0;
  memory_.resetHighWater();
}

}  // namespace radmesh::emu
