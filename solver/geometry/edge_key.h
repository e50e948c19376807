#pragma once
// A directed edge between two vertex indices as one hashable key: (from, to) and (to, from) differ.
#include <cstdint>

namespace radmesh {

inline std::uint64_t directedEdgeKey(int from, int to) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(from)) << 32) | static_cast<std::uint32_t>(to);
}

}  // namespace radmesh
