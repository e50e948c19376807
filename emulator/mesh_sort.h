#pragma once
// Sort on the mesh (section 1.5's form-factor phase): (key, value) pairs across the active PEs,
// ascending by key, in row-major PE order and, with lists, list order within a PE. A bitonic
// network over the n = k x P x Q elements (k per PE) whose element index is pe * k + slot: a
// compare-exchange at distance j < k stays inside a PE (ALU); a larger one pairs PE p with
// PE p xor (j / k), which on a power-of-two torus is an xnet exchange east-west or north-south
// at that distance, charged as two shifts of the PE's k pairs. Inactive PEs take no part: their
// pairs stay put, and the sorted pairs are routed to the active PEs in order (a scan for the
// ranks and a router send). Ties keep a deterministic but unspecified order.
//
// Distributed (transport.h), the same network runs over the blocks (detail::sortAcross), so the
// result is the one-process machine's bit for bit, ties included: with power-of-two blocks, a
// compare-exchange partner is in the same block, or in the same place of one partner rank's block,
// and the two ranks swap their blocks' pairs (a pairwise exchange) and each keeps its half.
#include <algorithm>
#include <stdexcept>
#include <vector>

#include "emulator/pe_array.h"
#include "emulator/plural.h"
#include "emulator/router.h"

namespace radmesh::emu {

namespace detail {
// Refuses shapes a bitonic network cannot cover; returns log2 of the element count.
int requireBitonicShape(const PeGrid& grid, int perPe);
// Charges the network's xnet exchanges and compare-exchanges for k pairs of pairBytes per PE.
void chargeBitonic(MeshMachine& machine, int perPe, std::int64_t pairBytes);
// Charges the rank scan and the router send that place sorted blocks on the active PEs (the send's
// traffic as routeTraffic counts it).
void chargePlacement(MeshMachine& machine, std::int64_t blockBytes);
void chargePlacement(MeshMachine& machine, std::int64_t blockBytes, const RouterStats& send);
// Refuses a rank grid the distributed network cannot pair (its sides must be powers of two).
void requireBitonicRanks(const MeshMachine& machine);

// Whether pair a sorts before pair b: absent pairs sort after every key.
template <class K>
bool sortsBefore(const K& aKey, bool aAbsent, const K& bKey, bool bAbsent) {
  if (aAbsent != bAbsent) return bAbsent;
  return !aAbsent && aKey < bKey;
}

template <class K, class V>
void bitonicSort(std::vector<K>& keys, std::vector<V>& values, std::vector<std::uint8_t>& absent) {
  const std::size_t n = keys.size();
  auto before = [&](std::size_t a, std::size_t b) { return sortsBefore(keys[a], absent[a], keys[b], absent[b]); };
  for (std::size_t size = 2; size <= n; size *= 2)
    for (std::size_t j = size / 2; j > 0; j /= 2)
      for (std::size_t block = 0; block < n; block += 2 * j) {
        const bool ascending = (block & size) == 0;
        for (std::size_t i = block; i < block + j; ++i)
          if (ascending ? before(i + j, i) : before(i, i + j)) {
            std::swap(keys[i], keys[i + j]);
            std::swap(values[i], values[i + j]);
            std::swap(absent[i], absent[i + j]);
          }
      }
}

template <class K, class V>
struct SortItem {
  K key{};
  V value{};
  std::uint8_t absent = 1;
};
// The compare-exchange of the network: whether the pairs at the lower and upper index swap.
template <class K, class V>
bool outOfOrder(const SortItem<K, V>& lower, const SortItem<K, V>& upper, bool ascending) {
  return ascending ? sortsBefore(upper.key, upper.absent, lower.key, lower.absent)
                   : sortsBefore(lower.key, lower.absent, upper.key, upper.absent);
}

// sortOnMesh over the blocks of a distributed machine: element pe * k + slot of the network is
// the block's item local(pe) * k + slot.
template <class K, class V, class Get, class Put>
void sortAcross(MeshMachine& machine, int perPe, Get get, Put put) {
  using Item = SortItem<K, V>;
  requireBitonicRanks(machine);
  const PeGrid& g = machine.grid();
  const PeBlock& b = machine.block();
  Transport& transport = machine.transport();
  const long long k = perPe, n = k * g.size();
  std::vector<Item> items(static_cast<std::size_t>(k) * b.size());
  for (int i = 0; i < b.size(); ++i) {
    if (!machine.mask().active(i)) continue;
    for (int s = 0; s < perPe; ++s) {
      Item& item = items[static_cast<std::size_t>(i) * k + s];
      get(machine.globalPe(i), s, item.key, item.value);
      item.absent = 0;
    }
  }
  chargeBitonic(machine, perPe, kWireBytes<K> + kWireBytes<V>);
  auto ascending = [](long long element, long long size) { return (element & size) == 0; };
  for (long long size = 2; size <= n; size *= 2)
    for (long long j = size / 2; j > 0; j /= 2) {
      if (j < k) {  // within each PE
        for (int i = 0; i < b.size(); ++i)
          for (long long s = 0; s < k; ++s) {
            const long long element = machine.globalPe(i) * k + s;
            if (element & j) continue;
            Item& lower = items[i * k + s];
            Item& upper = items[i * k + s + j];
            if (outOfOrder(lower, upper, ascending(element, size))) std::swap(lower, upper);
          }
        continue;
      }
      const long long d = j / k;  // partner PE = pe xor d: a column bit, or a row bit
      const bool columnBit = d < g.cols;
      const long long blockBit = columnBit ? d / b.cols : d / g.cols / b.rows;
      if (blockBit == 0) {  // the partner is in this block
        for (int i = 0; i < b.size(); ++i) {
          const int pe = machine.globalPe(i);
          if (pe & d) continue;
          const int partner = machine.local(static_cast<int>(pe ^ d));
          for (long long s = 0; s < k; ++s) {
            Item& lower = items[i * k + s];
            Item& upper = items[partner * k + s];
            if (outOfOrder(lower, upper, ascending(pe * k, size))) std::swap(lower, upper);
          }
        }
        continue;
      }
      const int partnerRank = columnBit ? transport.rankAt(transport.rankRow(), transport.rankCol() ^ static_cast<int>(blockBit))
                                        : transport.rankAt(transport.rankRow() ^ static_cast<int>(blockBit), transport.rankCol());
      const std::vector<Item> theirs = fromBytes<Item>(
          transport.exchange(Channel::Sort, partnerRank, toBytes(std::span<const Item>(items))));
      const bool iAmLower = (machine.globalPe(0) & d) == 0;
      for (int i = 0; i < b.size(); ++i) {
        const long long pe = machine.globalPe(i);
        for (long long s = 0; s < k; ++s) {
          Item& mine = items[i * k + s];
          const Item& other = theirs[i * k + s];
          const Item& lower = iAmLower ? mine : other;
          const Item& upper = iAmLower ? other : mine;
          const bool swap = outOfOrder(lower, upper, ascending(pe * k, size));
          mine = (iAmLower != swap) ? lower : upper;
        }
      }
    }
  // Sorted block p goes to the p-th active PE (in row-major order) unless every PE is active.
  const std::vector<Bytes> flags = transport.allGather(
      Channel::Sort, toBytes(std::span<const std::uint8_t>(machine.mask().flags(), b.size())));
  std::vector<int> activePes;
  std::vector<std::uint8_t> active(g.size(), 0);
  const RankGrid ranks = transport.rankGrid();
  for (int rr = 0; rr < ranks.rows; ++rr)
    for (int rc = 0; rc < ranks.cols; ++rc) {
      const PeBlock theirs = blockOf(g, ranks, rr, rc);
      const Bytes& f = flags[transport.rankAt(rr, rc)];
      for (int i = 0; i < theirs.size(); ++i) active[theirs.globalPe(g, i)] = static_cast<std::uint8_t>(f[i]);
    }
  for (int pe = 0; pe < g.size(); ++pe)
    if (active[pe]) activePes.push_back(pe);
  if (static_cast<int>(activePes.size()) == g.size()) {
    for (int i = 0; i < b.size(); ++i)
      for (int s = 0; s < perPe; ++s) {
        const Item& item = items[static_cast<std::size_t>(i) * k + s];
        put(machine.globalPe(i), s, item.key, item.value);
      }
    return;
  }
  std::vector<Message<Item>> out;
  std::vector<Link> sent, arrived;
  for (int i = 0; i < b.size(); ++i) {
    const int pe = machine.globalPe(i);
    if (pe >= static_cast<int>(activePes.size())) continue;
    sent.push_back({pe, activePes[pe]});
    for (int s = 0; s < perPe; ++s) out.push_back({pe, activePes[pe], s, items[static_cast<std::size_t>(i) * k + s]});
  }
  const std::vector<Message<Item>> placed = deliver(machine, Channel::Sort, out);
  for (const auto& m : placed)
    if (m.slot == 0) arrived.push_back({m.from, m.to});
  chargePlacement(machine, perPe * (kWireBytes<K> + kWireBytes<V>), routeTrafficAcross(machine, Channel::Sort, sent, arrived));
  for (const auto& m : placed) put(m.to, m.slot, m.payload.key, m.payload.value);
}

// Sorts k pairs per active PE read through get(pe, slot) and written back through put(pe,
// slot, key, value).
template <class K, class V, class Get, class Put>
void sortOnMesh(MeshMachine& machine, int perPe, Get get, Put put) {
  requireBitonicShape(machine.grid(), perPe);
  if (machine.distributed()) return sortAcross<K, V>(machine, perPe, get, put);
  const std::size_t n = static_cast<std::size_t>(perPe) * machine.size();
  std::vector<K> keys(n);
  std::vector<V> values(n);
  std::vector<std::uint8_t> absent(n, 1);
  for (int pe = 0; pe < machine.size(); ++pe) {
    if (!machine.active(pe)) continue;
    for (int s = 0; s < perPe; ++s) {
      const std::size_t i = static_cast<std::size_t>(pe) * perPe + s;
      get(pe, s, keys[i], values[i]);
      absent[i] = 0;
    }
  }
  chargeBitonic(machine, perPe, kWireBytes<K> + kWireBytes<V>);
  bitonicSort(keys, values, absent);
  if (!machine.mask().allActive()) chargePlacement(machine, perPe * (kWireBytes<K> + kWireBytes<V>));
  std::size_t next = 0;  // sorted pairs go to the active PEs in order
  for (int pe = 0; pe < machine.size(); ++pe) {
    if (!machine.active(pe)) continue;
    for (int s = 0; s < perPe; ++s, ++next) put(pe, s, keys[next], values[next]);
  }
}
}  // namespace detail

// One pair per PE. The grid's sides must be powers of two (as the MP-1's are).
template <class K, class V>
void sortPairs(MeshMachine& machine, Plural<K>& keys, Plural<V>& values) {
  const HostTimer timer = machine.timeHost(machine.counters().sort);
  requireSameMachine(machine, keys.machine(), "sortPairs");
  requireSameMachine(machine, values.machine(), "sortPairs");
  detail::sortOnMesh<K, V>(
      machine, 1, [&](int pe, int, K& k, V& v) { k = keys[pe], v = values[pe]; },
      [&](int pe, int, const K& k, const V& v) { keys[pe] = k, values[pe] = v; });
}

// k pairs per PE: every active PE's key and value lists must hold the same k, a power of two.
template <class K, class V>
void sortPairs(MeshMachine& machine, PeArray<K>& keys, PeArray<V>& values) {
  const HostTimer timer = machine.timeHost(machine.counters().sort);
  requireSameMachine(machine, keys.machine(), "sortPairs");
  requireSameMachine(machine, values.machine(), "sortPairs");
  // Every active PE must hold as many pairs as the first active one.
  detail::Problem first, uneven;
  for (int i = 0; i < machine.blockSize() && !first.found(); ++i)
    if (machine.mask().active(i)) first.note(machine.globalPe(i), keys.count(machine.globalPe(i)));
  first = detail::firstProblem(machine, Channel::Sort, first);
  const int perPe = first.found() ? static_cast<int>(first.a) : -1;
  for (int i = 0; i < machine.blockSize(); ++i) {
    const int pe = machine.globalPe(i);
    if (machine.mask().active(i) && (keys.count(pe) != perPe || values.count(pe) != perPe))
      uneven.note(pe, keys.count(pe), values.count(pe));
  }
  uneven = detail::firstProblem(machine, Channel::Sort, uneven);
  if (uneven.found())
    throw std::invalid_argument("sortPairs: " + machine.grid().name(uneven.pe) + " holds " +
                                std::to_string(uneven.a) + " keys and " + std::to_string(uneven.b) +
                                " values where every active PE must hold " + std::to_string(perPe) +
                                " of each");
  if (perPe <= 0) return;
  detail::sortOnMesh<K, V>(
      machine, perPe, [&](int pe, int s, K& k, V& v) { k = keys.at(pe, s), v = values.at(pe, s); },
      [&](int pe, int s, const K& k, const V& v) { keys.at(pe, s) = k, values.at(pe, s) = v; });
}

}  // namespace radmesh::emu
