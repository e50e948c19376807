#pragma once
// Global reductions over the active PEs (section 1.5: the shooting patch by reduceMax). Values
// are combined in row-major PE order; the cost is that of a recursive-doubling tree (tree_cost.h).
// Distributed (transport.h): reduceMax and an integer reduceAdd combine each block's result with
// one all-reduce (exact in any order); a floating-point reduceAdd gathers the active values and
// adds them in row-major order on every rank, since a sum in another order has other bits.
#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "emulator/distributed.h"
#include "emulator/plural.h"
#include "emulator/tree_cost.h"

namespace radmesh::emu {

template <class T>
struct Located {
  T value{};
  int pe = -1;  // -1 when no PE is active
};

namespace detail {
template <class T>
bool isNaN(const T& value) {
  if constexpr (std::is_floating_point_v<T>) return std::isnan(value);
  return false;
}
[[noreturn]] inline void throwNaN(const MeshMachine& machine, int pe, const char* operation) {
  throw std::domain_error(std::string(operation) + ": " + machine.grid().name(pe) +
                          " holds NaN, which has no order; fix the computation that made it");
}

template <class T>
struct AtPe {  // a value and its PE, as gathered
  int pe = 0;
  T value{};
};
}  // namespace detail

// The largest value over the active PEs and where it is; ties go to the lowest PE index.
template <class T>
Located<T> reduceMax(MeshMachine& machine, const Plural<T>& values) {
  const HostTimer timer = machine.timeHost(machine.counters().reduce);
  requireSameMachine(machine, values.machine(), "reduceMax");
  detail::chargeTree(machine.counters().reduce, machine.grid(), 1, kWireBytes<T> + kWireBytes<int>,
                     std::is_floating_point_v<T>);
  Located<T> best;
  detail::Problem nan;
  for (int i = 0; i < machine.blockSize(); ++i) {
    if (!machine.mask().active(i)) continue;
    const T& value = values.values()[i];
    const int pe = machine.globalPe(i);
    if (detail::isNaN(value)) {
      nan.note(pe, 0);
      break;
    }
    if (best.pe < 0 || best.value < value) best = {value, pe};
  }
  if constexpr (std::is_floating_point_v<T>) nan = detail::firstProblem(machine, Channel::Reduce, nan);
  if (nan.found()) detail::throwNaN(machine, nan.pe, "reduceMax");
  if (!machine.distributed()) return best;
  return detail::allReduce(machine, Channel::Reduce, best, [](const Located<T>& in, Located<T>& inout) {
    if (in.pe < 0) return;
    if (inout.pe < 0 || inout.value < in.value || (!(in.value < inout.value) && in.pe < inout.pe)) inout = in;
  });
}

// The sum over the active PEs, added in row-major order from T{} (so the same bits every run).
template <class T>
T reduceAdd(MeshMachine& machine, const Plural<T>& values) {
  const HostTimer timer = machine.timeHost(machine.counters().reduce);
  requireSameMachine(machine, values.machine(), "reduceAdd");
  detail::chargeTree(machine.counters().reduce, machine.grid(), 1, kWireBytes<T>,
                     std::is_floating_point_v<T>);
  if (machine.distributed() && !std::is_integral_v<T>) {
    std::vector<detail::AtPe<T>> mine;
    for (int i = 0; i < machine.blockSize(); ++i)
      if (machine.mask().active(i)) mine.push_back({machine.globalPe(i), values.values()[i]});
    T sum{};
    for (const auto& v : detail::gatherByPe(machine, Channel::Reduce, mine)) sum = sum + v.value;
    return sum;
  }
  T sum{};
  for (int i = 0; i < machine.blockSize(); ++i)
    if (machine.mask().active(i)) sum = sum + values.values()[i];
  return machine.distributed() ? detail::allSum(machine, Channel::Reduce, sum) : sum;
}

}  // namespace radmesh::emu
