#include "emulator/mesh_sort.h"

#include <string>

#include "emulator/router.h"
#include "emulator/tree_cost.h"

namespace radmesh::emu::detail {

namespace {
bool powerOfTwo(long long x) { return x > 0 && (x & (x - 1)) == 0; }
int log2Exact(long long x) {
  int l = 0;
  while ((1LL << l) < x) ++l;
  return l;
}
}  // namespace

int requireBitonicShape(const PeGrid& grid, int perPe) {
  if (!powerOfTwo(grid.rows) || !powerOfTwo(grid.cols))
    throw std::invalid_argument("sortPairs: the bitonic sort needs power-of-two grid sides, not " +
                                std::to_string(grid.rows) + " x " + std::to_string(grid.cols) +
                                "; configure the machine with power-of-two rows and cols");
  if (!powerOfTwo(perPe))
    throw std::invalid_argument("sortPairs: " + std::to_string(perPe) +
                                " pairs per PE is not a power of two; pad the lists");
  return log2Exact(static_cast<long long>(perPe) * grid.size());
}

void chargeBitonic(MeshMachine& machine, int perPe, std::int64_t pairBytes) {
  const PeGrid& g = machine.grid();
  const long long n = static_cast<long long>(perPe) * g.size();
  ClassCounts& c = machine.counters().sort;
  c.ops += 1;
  for (long long size = 2; size <= n; size *= 2)
    for (long long j = size / 2; j > 0; j /= 2) {
      if (j < perPe) {
        c.intOps += perPe / 2;  // compare-exchanges between slots of one PE
        continue;
      }
      const long long peDistance = j / perPe;  // a column bit, or a row bit beyond the columns
      const long long hops = peDistance < g.cols ? peDistance : peDistance / g.cols;
      c.hops += 2 * hops;  // each PE sends its k pairs to its partner and receives the partner's
      c.byteHops += 2 * hops * perPe * pairBytes;
      c.intOps += perPe;  // each PE keeps the lower or upper of each compared pair
    }
}

void chargePlacement(MeshMachine& machine, std::int64_t blockBytes) {
  // Sorted block r sits on PE r and goes to the r-th active PE.
  std::vector<int> destination(machine.size(), 0);
  std::vector<std::uint8_t> sends(machine.size(), 0);
  int rank = 0;
  for (int pe = 0; pe < machine.size(); ++pe)
    if (machine.active(pe)) sends[rank] = 1, destination[rank++] = pe;
  chargePlacement(machine, blockBytes, routeTraffic(machine.grid(), sends, destination));
}

void chargePlacement(MeshMachine& machine, std::int64_t blockBytes, const RouterStats& send) {
  ClassCounts& c = machine.counters().sort;
  chargeTree(c, machine.grid(), 2, sizeof(int), false);  // ranks of the active PEs
  chargeRoute(machine, c, send, blockBytes, 1);
}

void requireBitonicRanks(const MeshMachine& machine) {
  const RankGrid ranks = machine.transport().rankGrid();
  if (!powerOfTwo(ranks.rows) || !powerOfTwo(ranks.cols))
    throw std::invalid_argument("sortPairs: the distributed bitonic sort needs a power-of-two rank grid, not " +
                                std::to_string(ranks.rows) + " x " + std::to_string(ranks.cols) +
                                "; run on 1, 2, 4, 8, ... ranks");
}

}  // namespace radmesh::emu::detail
