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
}  // namespace

MeshMachine::MeshMachine(const MachineConfig& config)
    : grid_{checked(config).rows, config.cols},
      mask_(grid_.size()),
      memory_(grid_, config.memoryBudgetBytes),
      pool_(config.threads) {}

void requireSameMachine(const MeshMachine& expected, const MeshMachine& got, const char* operation) {
  if (&expected != &got)
    throw std::invalid_argument(std::string(operation) +
                                ": its plural data belong to different machines");
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
