#include "emulator/pe_grid.h"

namespace radmesh::emu {

int PeGrid::index(int row, int col) const {
  const int r = ((row % rows) + rows) % rows;
  const int c = ((col % cols) + cols) % cols;
  return r * cols + c;
}

}  // namespace radmesh::emu
