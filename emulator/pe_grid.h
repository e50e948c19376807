#pragma once
// Shape of a toroidal P x Q grid of processing elements and its index arithmetic.
namespace radmesh::emu {

struct PeGrid {
  int rows = 64;
  int cols = 64;
  int size() const { return rows * cols; }
  int index(int row, int col) const;  // wraps row and col around the torus
};

}  // namespace radmesh::emu
