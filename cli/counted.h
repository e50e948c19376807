#pragma once
// "1 portal", "2 portals": a count and its noun, for lines a person reads.
#include <fmt/format.h>

#include <string>
#include <string_view>

namespace radmesh::cli {

inline std::string counted(long long count, std::string_view noun, std::string_view plural = "") {
  if (count == 1) return fmt::format("1 {}", noun);
  return plural.empty() ? fmt::format("{} {}s", count, noun) : fmt::format("{} {}", count, plural);
}

}  // namespace radmesh::cli
