#include "emulator/pe_block.h"

#include <stdexcept>
#include <string>

namespace radmesh::emu {

namespace {
void requireSplit(int pes, int parts, const char* side) {
  const int block = pes / parts;
  if (pes % parts != 0 || (parts > 1 && block % kClusterSide != 0))
    throw std::invalid_argument("a distributed mesh of " + std::to_string(pes) + " PE " + side +
                                " cannot be split into " + std::to_string(parts) +
                                " blocks of whole 4 x 4 clusters; use a rank count whose grid "
                                "divides the PE grid into blocks of a multiple of 4 " + side);
}
}  // namespace

PeBlock blockOf(const PeGrid& grid, RankGrid ranks, int rankRow, int rankCol) {
  requireSplit(grid.rows, ranks.rows, "rows");
  requireSplit(grid.cols, ranks.cols, "cols");
  const int rows = grid.rows / ranks.rows, cols = grid.cols / ranks.cols;
  return {rankRow * rows, rankCol * cols, rows, cols};
}

}  // namespace radmesh::emu
