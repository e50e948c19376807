#include "emulator/xnet.h"

#include <string>

namespace radmesh::emu::detail {

void requireDistance(int distance, const char* operation) {
  if (distance < 0)
    throw std::invalid_argument(std::string(operation) + ": distance " + std::to_string(distance) +
                                " is negative; shift the opposite direction instead");
}

const std::vector<int>& xnetSources(const PeGrid& grid, Direction direction, int distance) {
  const Step s = stepOf(direction);
  const auto wrap = [](long long v, int m) { return static_cast<int>(((v % m) + m) % m); };
  thread_local std::vector<int> sourceColumn, from;
  sourceColumn.resize(grid.cols);
  for (int c = 0; c < grid.cols; ++c) sourceColumn[c] = wrap(c - static_cast<long long>(s.dCol) * distance, grid.cols);
  from.resize(grid.size());
  for (int r = 0; r < grid.rows; ++r) {
    const int base = wrap(r - static_cast<long long>(s.dRow) * distance, grid.rows) * grid.cols;
    for (int c = 0; c < grid.cols; ++c) from[r * grid.cols + c] = base + sourceColumn[c];
  }
  return from;
}

void chargeXnet(MeshMachine& machine, std::int64_t items, int distance, std::int64_t itemBytes) {
  ClassCounts& c = machine.counters().xnet;
  c.ops += items;
  c.hops += items * distance;
  c.byteHops += items * distance * itemBytes;
}

}  // namespace radmesh::emu::detail
