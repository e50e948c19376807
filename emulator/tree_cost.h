#pragma once
// Reductions and scans are computed on the host in row-major order (deterministic whatever the
// thread count) and charged as the recursive-doubling tree a mesh would run: along each row,
// then down the columns, with shift distances 1, 2, 4, ... (docs/emulator-cost-model.md).
#include <cstdint>

#include "emulator/mesh_machine.h"

namespace radmesh::emu::detail {

// Tree levels and summed shift distances over both grid dimensions.
struct TreeShape {
  int levels = 0;
  std::int64_t hops = 0;
};
TreeShape treeShape(const PeGrid& grid);

// Charges `sweeps` passes of the tree (1 for a reduction, 2 for a scan's up and down sweeps)
// moving itemBytes per PE, with one combine per level, as flops or integer operations.
void chargeTree(ClassCounts& counts, const PeGrid& grid, int sweeps, std::int64_t itemBytes,
                bool floatingCombine);

}  // namespace radmesh::emu::detail
