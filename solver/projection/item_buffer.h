#pragma once
// The item buffer (the paper's section 1.3): per pixel of a projection surface, the patch seen
// there after z-buffering, and how near it is.
#include <vector>

namespace radmesh {

struct ItemBuffer {
  static constexpr int kNone = -1;

  int width = 0;
  int height = 0;
  std::vector<int> items;             // patch index per pixel, row-major; kNone where nothing is seen
  std::vector<double> inverseDepth;   // 1/depth of that patch at the pixel centre; 0 where none

  ItemBuffer() = default;
  ItemBuffer(int widthPixels, int heightPixels);

  void clearRows(int rowBegin, int rowEnd);  // back to "nothing seen"
  int index(int column, int row) const { return row * width + column; }
  int item(int column, int row) const { return items[index(column, row)]; }
};

}  // namespace radmesh
