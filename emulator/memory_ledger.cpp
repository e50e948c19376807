#include "emulator/memory_ledger.h"

namespace radmesh::emu {

MemoryBudgetError::MemoryBudgetError(const std::string& what, int pe, std::int64_t neededBytes,
                                     std::int64_t budgetBytes)
    : std::runtime_error(what), pe_(pe), neededBytes_(neededBytes), budgetBytes_(budgetBytes) {}

void MemoryLedger::reserve(std::int64_t bytes, std::string_view label, int pe) {
  const std::int64_t needed = usedBytes_ + bytes;
  if (needed > budgetBytes_) {
    throw MemoryBudgetError(
        grid_.name(pe) + " needs " + std::to_string(needed) + " bytes of local memory (" +
            std::to_string(bytes) + " more for '" + std::string(label) + "' on top of " +
            std::to_string(usedBytes_) + " in use), but the per-PE budget is " +
            std::to_string(budgetBytes_) +
            " bytes. Fix: spread the data over more PEs (a larger grid), store less per PE, or "
            "raise MachineConfig::memoryBudgetBytes.",
        pe, needed, budgetBytes_);
  }
  usedBytes_ = needed;
  if (usedBytes_ > highWaterBytes_) highWaterBytes_ = usedBytes_;
}

}  // namespace radmesh::emu
