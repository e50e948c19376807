#pragma once
// The voxel grid findCells labels (docs/cells.md): free space, solid, and which cell each free
// voxel belongs to. Internal to solver/cells/.
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

using Index3 = std::array<int, 3>;

// The start of running minima and maxima, here and in the files of solver/cells/ that use the grid.
inline constexpr double kInf = std::numeric_limits<double>::infinity();

struct VoxelGrid {
  Vec3 origin{0.0};
  double voxel = 0.0;  // edge, metres
  Index3 n{0, 0, 0};
  long size() const { return long(n[0]) * n[1] * n[2]; }
  long index(const Index3& v) const { return (long(v[2]) * n[1] + v[1]) * n[0] + v[0]; }
  Index3 coords(long i) const { return {int(i % n[0]), int(i / n[0] % n[1]), int(i / (long(n[0]) * n[1]))}; }
  long stride(int axis) const { return axis == 0 ? 1 : axis == 1 ? n[0] : long(n[0]) * n[1]; }
  bool inside(const Index3& v) const {
    return v[0] >= 0 && v[1] >= 0 && v[2] >= 0 && v[0] < n[0] && v[1] < n[1] && v[2] < n[2];
  }
  Index3 voxelOf(const Vec3& p) const {
    Index3 v;
    for (int a = 0; a < 3; ++a) v[a] = int(std::floor((p[a] - origin[a]) / voxel));
    return v;
  }
  Vec3 corner(const Index3& v) const { return origin + voxel * Vec3(v[0], v[1], v[2]); }
};

inline constexpr std::int32_t kUnreached = -2;  // free, but joined to no core (inside a wall's thickness)
inline constexpr std::int32_t kSolid = -3;

struct VoxelLabels {
  std::vector<std::int32_t> label;  // per voxel: a cell, kOutsideCell, kUnreached or kSolid
  int cells = 0;
};

}  // namespace radmesh
