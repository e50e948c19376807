#pragma once
// Per-PE local memory (16 KB on the MP-1, section 1.4). A SIMD machine lays a plural variable or a
// plural array at the same address on every PE, so each PE reserves the same bytes: the ledger
// keeps that one per-PE figure, its high-water mark, and refuses what would exceed the budget.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "emulator/pe_grid.h"

namespace radmesh::emu {

// Raised when a PE would need more local memory than the budget.
class MemoryBudgetError : public std::runtime_error {
 public:
  MemoryBudgetError(const std::string& what, int pe, std::int64_t neededBytes,
                    std::int64_t budgetBytes);
  int pe() const { return pe_; }
  std::int64_t neededBytes() const { return neededBytes_; }
  std::int64_t budgetBytes() const { return budgetBytes_; }

 private:
  int pe_;
  std::int64_t neededBytes_;
  std::int64_t budgetBytes_;
};

class MemoryLedger {
 public:
  MemoryLedger(PeGrid grid, std::int64_t budgetBytes) : grid_(grid), budgetBytes_(budgetBytes) {}

  // Reserves `bytes` more on every PE for `label`; `pe` is the PE whose need forced it (for the
  // message). Throws MemoryBudgetError and reserves nothing when the budget would be exceeded.
  void reserve(std::int64_t bytes, std::string_view label, int pe = 0);
  void release(std::int64_t bytes) { usedBytes_ -= bytes; }

  std::int64_t usedBytes() const { return usedBytes_; }
  std::int64_t highWaterBytes() const { return highWaterBytes_; }
  std::int64_t budgetBytes() const { return budgetBytes_; }
  void resetHighWater() { highWaterBytes_ = usedBytes_; }

 private:
  PeGrid grid_;
  std::int64_t budgetBytes_;
  std::int64_t usedBytes_ = 0;
  std::int64_t highWaterBytes_ = 0;
};

}  // namespace radmesh::emu
