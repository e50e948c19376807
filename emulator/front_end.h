#pragma once
// The front end (the MP-1's host) reading PE memory, and the figures a program that counts its own
// SIMD steps takes over the PEs. On one process these read its own memory; distributed
// (transport.h) they are collective: every process calls them together and gets the same answer.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "emulator/distributed.h"
#include "emulator/plural.h"

namespace radmesh::emu {

// PE pe's value: the process holding it tells the others.
template <class T>
T readPe(const Plural<T>& values, int pe) {
  MeshMachine& m = values.machine();
  if (!m.distributed()) return values[pe];
  struct Held {
    bool held = false;
    T value{};
  };
  const Held mine = m.holds(pe) ? Held{true, values[pe]} : Held{};
  return detail::allReduce(m, Channel::FrontEnd, mine, [](const Held& in, Held& inout) {
    if (in.held) inout = in;
  }).value;
}

// What this process's PEs hold, as records naming their PE (R has an int `pe`): every process's,
// in PE order (a PE's records in the order given); on one process, `mine` as given.
template <class R>
std::vector<R> gatherByPe(MeshMachine& m, std::vector<R> mine) {
  if (!m.distributed()) return mine;
  return detail::gatherByPe(m, Channel::FrontEnd, mine);
}

// The most any PE of any process took, given this process's most.
inline std::int64_t mostOverProcesses(MeshMachine& m, std::int64_t mine) {
  if (!m.distributed()) return mine;
  return detail::allReduce(m, Channel::Reduce, mine, [](std::int64_t in, std::int64_t& inout) {
    inout = std::max(inout, in);
  });
}

}  // namespace radmesh::emu
