#include "emulator/router.h"

#include <algorithm>
#include <string>

namespace radmesh::emu::detail {

RouterStats routeTraffic(const PeGrid& g, std::span<const std::uint8_t> sends,
                         std::span<const int> destinationPe) {
  RouterStats stats;
  stats.arrivals.assign(g.size(), 0);
  std::vector<int> sendersPerCluster(clusterCount(g), 0);
  std::vector<int> arrivalsPerCluster(clusterCount(g), 0);
  for (int pe = 0; pe < g.size(); ++pe) {
    if (!sends[pe]) continue;
    const int to = destinationPe[pe];
    if (to < 0 || to >= g.size())
      throw std::out_of_range(g.name(pe) + " addresses PE " + std::to_string(to) +
                              ", outside the " + std::to_string(g.rows) + " x " +
                              std::to_string(g.cols) +
                              " grid; deactivate PEs that have nothing to send");
    ++stats.messages;
    ++stats.arrivals[to];
    ++sendersPerCluster[clusterOf(g, pe)];
    ++arrivalsPerCluster[clusterOf(g, to)];
  }
  stats.maxArrivals = *std::max_element(stats.arrivals.begin(), stats.arrivals.end());
  stats.rounds = std::max(*std::max_element(sendersPerCluster.begin(), sendersPerCluster.end()),
                          *std::max_element(arrivalsPerCluster.begin(), arrivalsPerCluster.end()));
  return stats;
}

void chargeRoute(MeshMachine& machine, ClassCounts& counts, const RouterStats& stats,
                 std::int64_t payloadBytes, int passes) {
  counts.ops += 1;
  counts.messages += stats.messages;
  counts.rounds += static_cast<std::int64_t>(passes) * stats.rounds;
  counts.byteRounds += static_cast<std::int64_t>(stats.rounds) * payloadBytes;
  auto& worst = machine.counters().maxCollisions;
  worst = std::max<std::int64_t>(worst, stats.maxArrivals);
}

}  // namespace radmesh::emu::detail
