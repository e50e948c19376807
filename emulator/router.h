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
//
// Distributed (transport.h), the active PEs' messages go to the ranks holding their destinations
// in one all-to-all (detail::routeAcross); each block applies what arrived in source order, so every
// combining result is the one-process machine's.
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "emulator/distributed.h"
#include "emulator/pe_array.h"
#include "emulator/plural.h"

namespace radmesh::emu {

enum class Combine { Add, Min, Max, Overwrite };

struct RouterStats {
  std::int64_t messages = 0;  // messages delivered
  int maxArrivals = 0;        // collisions: most messages arriving at one PE
  int rounds = 0;             // serialized passes through the busiest cluster port
  std::vector<int> arrivals;  // messages per destination PE (distributed: the block's PEs only)
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
[[noreturn]] void throwBadDestination(const PeGrid& grid, int pe, int to);

// Distributed: a message from PE `from` to PE `to` (into element `slot` where it matters).
template <class T>
struct Message {
  int from = 0;
  int to = 0;
  int slot = 0;
  T payload{};
};
struct Link {
  int from = 0;
  int to = 0;
};
// routeTraffic over the ranks: this block's messages sent (destinations checked by every rank
// alike) and those delivered to it; the counts are the whole machine's.
void requireDestinations(MeshMachine& machine, Channel channel, std::span<const Link> sent);
RouterStats routeTrafficAcross(MeshMachine& machine, Channel channel, std::span<const Link> sent,
                               std::span<const Link> arrived);

template <class T>
struct Routed {
  std::vector<Message<T>> arrived;  // at this block's PEs, in increasing source order
  RouterStats stats;
};
// Every active block PE sends what fill(pe, message) puts in its message to destinationPe.
template <class T, class Fill>
Routed<T> routeAcross(MeshMachine& machine, Channel channel, const Plural<int>& destinationPe, Fill fill) {
  std::vector<Message<T>> out;
  std::vector<Link> sent;
  for (int i = 0; i < machine.blockSize(); ++i) {
    if (!machine.mask().active(i)) continue;
    const int pe = machine.globalPe(i);
    sent.push_back({pe, destinationPe[pe]});
  }
  requireDestinations(machine, channel, sent);
  for (const Link& link : sent) {
    Message<T> message{link.from, link.to, 0, T{}};
    fill(link.from, message);
    out.push_back(message);
  }
  Routed<T> routed{deliver(machine, channel, out), {}};
  std::vector<Link> arrived;
  for (const Message<T>& m : routed.arrived) arrived.push_back({m.from, m.to});
  routed.stats = routeTrafficAcross(machine, channel, sent, arrived);
  return routed;
}
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
  if (machine.distributed()) {
    detail::Routed<T> routed = detail::routeAcross<T>(
        machine, Channel::Router, destinationPe, [&](int pe, detail::Message<T>& m) { m.payload = src[pe]; });
    detail::chargeRoute(machine, machine.counters().router, routed.stats, kWireBytes<T>, 1);
    for (const auto& m : routed.arrived) detail::combineInto(dst[m.to], m.payload, combine);
    return std::move(routed.stats);
  }
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
  // The first message (by source PE) into an element its destination does not hold.
  detail::Problem wrongSlot;
  auto check = [&](int from, int to, int slot) {
    if (slot < 0 || slot >= dst.count(to)) wrongSlot.note(from, slot, to, dst.count(to));
  };
  auto refuseWrongSlot = [&] {
    if (!wrongSlot.found()) return;
    throw std::out_of_range(machine.grid().name(wrongSlot.pe) + " sends to element " + std::to_string(wrongSlot.a) +
                            " of '" + dst.label() + "' on PE " + std::to_string(wrongSlot.b) +
                            ", which holds " + std::to_string(wrongSlot.c));
  };
  if (machine.distributed()) {
    detail::Routed<T> routed = detail::routeAcross<T>(machine, Channel::Router, destinationPe,
                                                      [&](int pe, detail::Message<T>& m) {
                                                        m.slot = destinationSlot[pe];
                                                        m.payload = src[pe];
                                                      });
    for (const auto& m : routed.arrived) check(m.from, m.to, m.slot);
    wrongSlot = detail::firstProblem(machine, Channel::Router, wrongSlot);
    refuseWrongSlot();
    detail::chargeRoute(machine, machine.counters().router, routed.stats, kWireBytes<T> + kWireBytes<int>, 1);
    for (const auto& m : routed.arrived) detail::combineInto(dst.at(m.to, m.slot), m.payload, combine);
    return std::move(routed.stats);
  }
  RouterStats stats = detail::routeTraffic(machine.grid(), detail::activeFlags(machine), destinationPe.values());
  for (int pe = 0; pe < machine.size(); ++pe)
    if (machine.active(pe)) check(pe, destinationPe[pe], destinationSlot[pe]);
  refuseWrongSlot();
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
  if (machine.distributed()) {
    detail::Routed<T> routed = detail::routeAcross<T>(
        machine, Channel::Router, destinationPe, [&](int pe, detail::Message<T>& m) { m.payload = src[pe]; });
    detail::MaxAt need;
    for (int i = 0; i < machine.blockSize(); ++i) {
      const int pe = machine.globalPe(i);
      if (dst.count(pe) + routed.stats.arrivals[pe] > need.value) need = {dst.count(pe) + routed.stats.arrivals[pe], pe};
    }
    need = detail::allMaxAt(machine, Channel::Router, need);
    dst.reserve(static_cast<int>(need.value), need.pe);
    detail::chargeRoute(machine, machine.counters().router, routed.stats, kWireBytes<T>, 1);
    for (const auto& m : routed.arrived) dst.pushReserved(m.to, m.payload);
    return std::move(routed.stats);
  }
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
  if (machine.distributed()) {  // requests to the sources' blocks, replies back to the requesters
    detail::Routed<T> requests = detail::routeAcross<T>(machine, Channel::Router, sourcePe,
                                                        [](int, detail::Message<T>&) {});
    detail::chargeRoute(machine, machine.counters().router, requests.stats, kWireBytes<T>, 2);
    std::vector<detail::Message<T>> replies;
    for (const auto& m : requests.arrived) replies.push_back({m.from, m.from, 0, src[m.to]});
    for (const auto& m : detail::deliver(machine, Channel::Router, replies)) dst[m.to] = m.payload;
    return std::move(requests.stats);
  }
  RouterStats stats = detail::routeTraffic(machine.grid(), detail::activeFlags(machine), sourcePe.values());
  detail::chargeRoute(machine, machine.counters().router, stats, kWireBytes<T>, 2);
  std::vector<T> read(src.data(), src.data() + src.size());  // dst may alias src
  for (int pe = 0; pe < machine.size(); ++pe)
    if (machine.active(pe)) dst[pe] = read[sourcePe[pe]];
  return stats;
}

}  // namespace radmesh::emu
