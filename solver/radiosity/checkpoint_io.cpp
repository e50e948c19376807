// The bounds checks of reading a checkpoint, and the element counts written before each container:
// the byte-level steps of checkpoint_io.h that need no template.
#include "solver/radiosity/checkpoint_io.h"

#include <cstring>

namespace radmesh::checkpoint_io {

std::size_t Writer::count(std::size_t n) {
  std::uint64_t c = n;
  scalar(c);
  return n;
}

void Reader::raw(char* data, std::size_t n) {
  if (n > bytes_.size() - at_) throw Malformed{};
  std::memcpy(data, bytes_.data() + at_, n);
  at_ += n;
}

std::size_t Reader::count(std::size_t) {
  std::uint64_t c = 0;
  scalar(c);
  if (c > bytes_.size() - at_) throw Malformed{};  // every element takes at least a byte
  return static_cast<std::size_t>(c);
}

}  // namespace radmesh::checkpoint_io
