#pragma once
// Sort on the mesh (section 1.5's form-factor phase): (key, value) pairs across the active PEs,
// ascending by key, in row-major PE order and, with lists, list order within a PE. A bitonic
// network over the n = k x P x Q elements (k per PE) whose element index is pe * k + slot: a
// compare-exchange at distance j < k stays inside a PE (ALU); a larger one pairs PE p with
// PE p xor (j / k), which on a power-of-two torus is an xnet exchange east-west or north-south
// at that distance, charged as two shifts of the PE's k pairs. Inactive PEs take no part: their
// pairs stay put, and the sorted pairs are routed to the active PEs in order (a scan for the
// ranks and a router send). Ties keep a deterministic but unspecified order.
#include <algorithm>
#include <stdexcept>
#include <vector>

#include "emulator/pe_array.h"
#include "emulator/plural.h"

namespace radmesh::emu {

namespace detail {
// Refuses shapes a bitonic network cannot cover; returns log2 of the element count.
int requireBitonicShape(const PeGrid& grid, int perPe);
// Charges the network's xnet exchanges and compare-exchanges for k pairs of pairBytes per PE.
void chargeBitonic(MeshMachine& machine, int perPe, std::int64_t pairBytes);
// Charges the rank scan and the router send that place sorted blocks on the active PEs.
void chargePlacement(MeshMachine& machine, std::int64_t blockBytes);

template <class K, class V>
void bitonicSort(std::vector<K>& keys, std::vector<V>& values, std::vector<std::uint8_t>& absent) {
  const std::size_t n = keys.size();
  auto before = [&](std::size_t a, std::size_t b) {  // absent pairs sort after every key
    if (absent[a] != absent[b]) return absent[b] != 0;
    return !absent[a] && keys[a] < keys[b];
  };
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

// Sorts k pairs per active PE read through get(pe, slot) and written back through put(pe,
// slot, key, value).
template <class K, class V, class Get, class Put>
void sortOnMesh(MeshMachine& machine, int perPe, Get get, Put put) {
  requireBitonicShape(machine.grid(), perPe);
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
  int perPe = -1;
  for (int pe = 0; pe < machine.size(); ++pe) {
    if (!machine.active(pe)) continue;
    if (perPe < 0) perPe = keys.count(pe);
    if (keys.count(pe) != perPe || values.count(pe) != perPe)
      throw std::invalid_argument("sortPairs: " + machine.grid().name(pe) + " holds " +
                                  std::to_string(keys.count(pe)) + " keys and " +
                                  std::to_string(values.count(pe)) + " values where every active PE "
                                  "must hold " + std::to_string(perPe) + " of each");
  }
  if (perPe <= 0) return;
  detail::sortOnMesh<K, V>(
      machine, perPe, [&](int pe, int s, K& k, V& v) { k = keys.at(pe, s), v = values.at(pe, s); },
      [&](int pe, int s, const K& k, const V& v) { keys.at(pe, s) = k, values.at(pe, s) = v; });
}

}  // namespace radmesh::emu
