#include "emulator/pe_grid.h"

#include <stdexcept>

namespace radmesh::emu {

Step stepOf(Direction direction) {
  switch (direction) {
    case Direction::N: return {-1, 0};
    case Direction::NE: return {-1, 1};
    case Direction::E: return {0, 1};
    case Direction::SE: return {1, 1};
    case Direction::S: return {1, 0};
    case Direction::SW: return {1, -1};
    case Direction::W: return {0, -1};
    case Direction::NW: return {-1, -1};
  }
  throw std::logic_error("stepOf: unknown direction");
}

const char* toString(Direction direction) {
  static constexpr const char* kNames[] = {"N", "NE", "E", "SE", "S", "SW", "W", "NW"};
  return kNames[static_cast<int>(direction)];
}

namespace {
int wrap(long long value, int modulus) {
  const long long r = value % modulus;
  return static_cast<int>(r < 0 ? r + modulus : r);
}
}  // namespace

int PeGrid::index(int r, int c) const { return wrap(r, rows) * cols + wrap(c, cols); }

std::string PeGrid::name(int pe) const {
  return "PE (row " + std::to_string(row(pe)) + ", col " + std::to_string(col(pe)) + ")";
}

int clusterOf(const PeGrid& grid, int pe) {
  const int clusterCols = (grid.cols + kClusterSide - 1) / kClusterSide;
  return (grid.row(pe) / kClusterSide) * clusterCols + grid.col(pe) / kClusterSide;
}

int clusterCount(const PeGrid& grid) {
  return ((grid.rows + kClusterSide - 1) / kClusterSide) *
         ((grid.cols + kClusterSide - 1) / kClusterSide);
}

}  // namespace radmesh::emu
