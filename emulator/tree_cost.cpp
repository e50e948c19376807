#include "emulator/tree_cost.h"

namespace radmesh::emu::detail {

namespace {
void addDimension(TreeShape& shape, int extent) {
  for (std::int64_t d = 1; d < extent; d *= 2) {
    ++shape.levels;
    shape.hops += d;
  }
}
}  // namespace

TreeShape treeShape(const PeGrid& grid) {
  TreeShape shape;
  addDimension(shape, grid.cols);
  addDimension(shape, grid.rows);
  return shape;
}

void chargeTree(ClassCounts& counts, const PeGrid& grid, int sweeps, std::int64_t itemBytes,
                bool floatingCombine) {
  const TreeShape shape = treeShape(grid);
  counts.ops += 1;
  counts.hops += sweeps * shape.hops;
  counts.byteHops += sweeps * shape.hops * itemBytes;
  (floatingCombine ? counts.flops : counts.intOps) += sweeps * shape.levels;
}

}  // namespace radmesh::emu::detail
