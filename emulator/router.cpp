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
    if (to < 0 || to >= g.size()) throwBadDestination(g, pe, to);
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

void throwBadDestination(const PeGrid& g, int pe, int to) {
  throw std::out_of_range(g.name(pe) + " addresses PE " + std::to_string(to) + ", outside the " +
                          std::to_string(g.rows) + " x " + std::to_string(g.cols) +
                          " grid; deactivate PEs that have nothing to send");
}

void requireDestinations(MeshMachine& machine, Channel channel, std::span<const Link> sent) {
  Problem bad;
  for (const Link& link : sent)
    if (link.to < 0 || link.to >= machine.size()) bad.note(link.from, link.to);
  bad = firstProblem(machine, channel, bad);
  if (bad.found()) throwBadDestination(machine.grid(), bad.pe, static_cast<int>(bad.a));
}

RouterStats routeTrafficAcross(MeshMachine& machine, Channel channel, std::span<const Link> sent,
                               std::span<const Link> arrived) {
  const PeGrid& g = machine.grid();
  RouterStats stats;
  stats.arrivals.assign(g.size(), 0);
  // Blocks hold whole clusters (pe_block.h), so a cluster's senders and arrivals are all here.
  std::vector<int> sendersPerCluster(clusterCount(g), 0);
  std::vector<int> arrivalsPerCluster(clusterCount(g), 0);
  for (const Link& link : sent) ++sendersPerCluster[clusterOf(g, link.from)];
  for (const Link& link : arrived) ++stats.arrivals[link.to], ++arrivalsPerCluster[clusterOf(g, link.to)];
  struct Totals {
    std::int64_t messages;
    int maxArrivals;
    int rounds;
  } totals{static_cast<std::int64_t>(sent.size()), *std::max_element(stats.arrivals.begin(), stats.arrivals.end()),
           std::max(*std::max_element(sendersPerCluster.begin(), sendersPerCluster.end()),
                    *std::max_element(arrivalsPerCluster.begin(), arrivalsPerCluster.end()))};
  totals = allReduce(machine, channel, totals, [](const Totals& in, Totals& inout) {
    inout.messages += in.messages;
    inout.maxArrivals = std::max(inout.maxArrivals, in.maxArrivals);
    inout.rounds = std::max(inout.rounds, in.rounds);
  });
  stats.messages = totals.messages;
  stats.maxArrivals = totals.maxArrivals;
  stats.rounds = totals.rounds;
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
