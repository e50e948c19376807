#pragma once
// The router: the MP-1's multistage crossbar between arbitrary PEs (section 1.4). Active PEs
// send (or fetch); a destination receives whether or not it is active. Messages are processed
// in increasing source-PE order, which fixes every combining result:
//   Add:       dst += each message in turn;  Min / Max: dst = min / max(dst, messages...);
//   Overwrite: the message from the highest-numbered source PE wins.
// PEs that receive nothing keep their values.
//
// Cost (see docs/emulator-cost-model.md): the 16 PEs of a 4 x 4 cluster share one router port,
// so an operation takes as many serialized rounds as the busiest port has messages, counting
// both the senders in a source cluster and the arrivals into a destination cluster.
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "emulator/pe_array.h"
#include "emulator/plural.h"

namespace radmesh::emu {

enum class Combine { Add, Min, Max, Overwrite };

struct RouterStats {
  std::int64_t messages = 0;  // messages delivered
  int maxArrivals = 0;        // collisions: most messages arriving at one PE
  int rounds = 0;             // serialized passes through the busiest cluster port
  std::vector<int> arrivals;  // messages per destination PE
};

namespace detail {
// Checks the destination of every PE that sends (throws std::out_of_range naming the PE) and
// counts the traffic.
RouterStats routeTraffic(const PeGrid& grid, std::span<const std::uint8_t> sends,
                         std::span<const int> destinationPe);
inline std::span<const std::uint8_t> activeFlags(const MeshMachine& machine) {
  return {machine.mask().flags(), static_cast<std::size_t>(machine.size())};
}
// Adds one routing operation of `passes` passes (1 for a send, 2 for a fetch's request and
// reply) to `counts`, and raises the machine's worst collision count.
void chargeRoute(MeshMachine& machine, ClassCounts& counts, const RouterStats& stats,
                 std::int64_t payloadBytes, int passes);
}  // namespace detail

namespace detail {
template <class T>
void combineInto(T& to, const T& message, Combine combine) {
  switch (combine) {
    case Combine::Add: to = to + message; break;
    case Combine::Min: if (message < to) to = message; break;
    case Combine::Max: if (to < message) to = message; break;
    case Combine::Overwrite: to = message; break;
  }
}
}  // namespace detail

template <class T>
RouterStats routerSend(MeshMachine& machine, Plural<T>& dst, const Plural<T>& src,
                       const Plural<int>& destinationPe, Combine combine) {
  const HostTimer timer = machine.timeHost(machine.counters().router);
  requireSameMachine(machine, dst.machine(), "routerSend");
  requireSameMachine(machine, src.machine(), "routerSend");
  RouterStats stats = detail::routeTraffic(machine.grid(), detail::activeFlags(machine), destinationPe.values());
  detail::chargeRoute(machine, machine.counters().router, stats, kWireBytes<T>, 1);
  std::vector<T> sent(src.data(), src.data() + src.size());  // dst may alias src
  for (int pe = 0; pe < machine.size(); ++pe)
    if (machine.active(pe)) detail::combineInto(dst[destinationPe[pe]], sent[pe], combine);
  return stats;
}

// Sends into element destinationSlot of the destination PE's local array (which must hold it).
template <class T>
RouterStats routerSend(MeshMachine& machine, PeArray<T>& dst, const Plural<T>& src,
                       const Plural<int>& destinationPe, const Plural<int>& destinationSlot,
                       Combine combine) {
  const HostTimer timer = machine.timeHost(machine.counters().router);
  requireSameMachine(machine, dst.machine(), "routerSend");
  requireSameMachine(machine, src.machine(), "routerSend");
  RouterStats stats = detail::routeTraffic(machine.grid(), detail::activeFlags(machine), destinationPe.values());
  for (int pe = 0; pe < machine.size(); ++pe) {
    if (!machine.active(pe)) continue;
    const int slot = destinationSlot[pe];
    if (slot < 0 || slot >= dst.count(destinationPe[pe]))
      throw std::out_of_range(machine.grid().name(pe) + " sends to element " + std::to_string(slot) +
                              " of '" + dst.label() + "' on PE " + std::to_string(destinationPe[pe]) +
                              ", which holds " + std::to_string(dst.count(destinationPe[pe])));
  }
  detail::chargeRoute(machine, machine.counters().router, stats, kWireBytes<T> + kWireBytes<int>, 1);
  for (int pe = 0; pe < machine.size(); ++pe)
    if (machine.active(pe)) detail::combineInto(dst.at(destinationPe[pe], destinationSlot[pe]), src[pe], combine);
  return stats;
}

// Sends without combining: each message is appended to the destination PE's list, in increasing
// source order. stats.arrivals is each PE's depth of what arrived.
template <class T>
RouterStats routerSendAppend(MeshMachine& machine, PeArray<T>& dst, const Plural<T>& src,
                             const Plural<int>& destinationPe) {
  const HostTimer timer = machine.timeHost(machine.counters().router);
  requireSameMachine(machine, dst.machine(), "routerSendAppend");
  requireSameMachine(machine, src.machine(), "routerSendAppend");
  RouterStats stats = detail::routeTraffic(machine.grid(), detail::activeFlags(machine), destinationPe.values());
  int need = 0;
  int needAt = 0;
  for (int pe = 0; pe < machine.size(); ++pe)
    if (dst.count(pe) + stats.arrivals[pe] > need) need = dst.count(pe) + stats.arrivals[pe], needAt = pe;
  dst.reserve(need, needAt);
  detail::chargeRoute(machine, machine.counters().router, stats, kWireBytes<T>, 1);
  for (int pe = 0; pe < machine.size(); ++pe)
    if (machine.active(pe)) dst.pushReserved(destinationPe[pe], src[pe]);
  return stats;
}

// Each active PE reads src at sourcePe (a request pass and a reply pass); stats count requests.
template <class T>
RouterStats routerFetch(MeshMachine& machine, Plural<T>& dst, const Plural<T>& src,
                        const Plural<int>& sourcePe) {
  const HostTimer timer = machine.timeHost(machine.counters().router);
  requireSameMachine(machine, dst.machine(), "routerFetch");
  requireSameMachine(machine, src.machine(), "routerFetch");
  RouterStats stats = detail::routeTraffic(machine.grid(), detail::activeFlags(machine), sourcePe.values());
  detail::chargeRoute(machine, machine.counters().router, stats, kWireBytes<T>, 2);
  std::vector<T> read(src.data(), src.data() + src.size());  // dst may alias src
  for (int pe = 0; pe < machine.size(); ++pe)
    if (machine.active(pe)) dst[pe] = read[sourcePe[pe]];
  return stats;
}

}  // namespace radmesh::emu
