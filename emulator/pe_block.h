#pragma once
// The PEs one process holds: a rectangle of the torus (a block). One process holds the whole
// torus; a distributed machine (transport.h) splits it into equal blocks over a rows x cols grid
// of ranks, so that machines larger than one process could hold become possible.
#include "emulator/pe_grid.h"

namespace radmesh::emu {

struct RankGrid {
  int rows = 1;
  int cols = 1;
  int size() const { return rows * cols; }
};

struct PeBlock {
  int firstRow = 0;
  int firstCol = 0;
  int rows = 0;
  int cols = 0;

  int size() const { return rows * cols; }
  bool holds(const PeGrid& grid, int pe) const {
    const int r = grid.row(pe) - firstRow, c = grid.col(pe) - firstCol;
    return r >= 0 && r < rows && c >= 0 && c < cols;
  }
  // Local indices run row-major over the block, so they increase with the global PE id.
  int localIndex(const PeGrid& grid, int pe) const {
    return (grid.row(pe) - firstRow) * cols + grid.col(pe) - firstCol;
  }
  int globalPe(const PeGrid& grid, int local) const {
    return (firstRow + local / cols) * grid.cols + firstCol + local % cols;
  }
};

// The block of the rank at (rankRow, rankCol). The rank grid must divide the PE grid evenly, into
// blocks whose sides are multiples of the router's 4 x 4 clusters (or whole sides), so that no
// cluster port is shared between processes; throws std::invalid_argument naming the fix otherwise.
PeBlock blockOf(const PeGrid& grid, RankGrid ranks, int rankRow, int rankCol);

}  // namespace radmesh::emu
