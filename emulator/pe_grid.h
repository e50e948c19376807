#pragma once
// Shape of a toroidal P x Q grid of processing elements (the MasPar MP-1's PE array, section 1.4)
// and its index arithmetic. PEs are numbered row-major: pe = row * cols + col.
#include <string>

namespace radmesh::emu {

// The eight xnet directions. North is row - 1, east is col + 1.
enum class Direction { N, NE, E, SE, S, SW, W, NW };

struct Step {
  int dRow = 0;
  int dCol = 0;
};
Step stepOf(Direction direction);  // one hop in that direction
const char* toString(Direction direction);

struct PeGrid {
  int rows = 64;
  int cols = 64;

  int size() const { return rows * cols; }
  int row(int pe) const { return pe / cols; }
  int col(int pe) const { return pe % cols; }
  int index(int row, int col) const;  // wraps row and col around the torus
  // "PE (row 3, col 7)": how messages name a PE.
  std::string name(int pe) const;
};

// The MP-1 groups PEs into 4 x 4 clusters that share one router port (see
// docs/emulator-cost-model.md). Grids not divisible by 4 get partial clusters at the far edges.
inline constexpr int kClusterSide = 4;
int clusterOf(const PeGrid& grid, int pe);
int clusterCount(const PeGrid& grid);

}  // namespace radmesh::emu
