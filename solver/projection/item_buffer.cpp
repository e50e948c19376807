#include "solver/projection/item_buffer.h"

#include <algorithm>
#include <cstddef>

namespace radmesh {

ItemBuffer::ItemBuffer(int widthPixels, int heightPixels)
    : width(widthPixels),
      height(heightPixels),
      items(static_cast<std::size_t>(widthPixels) * heightPixels, kNone),
      inverseDepth(static_cast<std::size_t>(widthPixels) * heightPixels, 0.0) {}

void ItemBuffer::clearRows(int rowBegin, int rowEnd) {
  const auto begin = static_cast<std::ptrdiff_t>(rowBegin) * width;
  const auto end = static_cast<std::ptrdiff_t>(rowEnd) * width;
  std::fill(items.begin() + begin, items.begin() + end, kNone);
  std::fill(inverseDepth.begin() + begin, inverseDepth.begin() + end, 0.0);
}

}  // namespace radmesh
