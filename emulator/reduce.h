#pragma once
// Global reductions over the active PEs (section 1.5: the shooting patch by reduceMax). Values
// are combined in row-major PE order; the cost is that of a recursive-doubling tree (tree_cost.h).
#include <cmath>
#include <stdexcept>
#include <type_traits>

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
void refuseNaN(const MeshMachine& machine, const T& value, int pe, const char* operation) {
  if constexpr (std::is_floating_point_v<T>)
    if (std::isnan(value))
      throw std::domain_error(std::string(operation) + ": " + machine.grid().name(pe) +
                              " holds NaN, which has no order; fix the computation that made it");
}
}  // namespace detail

// The largest value over the active PEs and where it is; ties go to the lowest PE index.
template <class T>
Located<T> reduceMax(MeshMachine& machine, const Plural<T>& values) {
  const HostTimer timer = machine.timeHost(machine.counters().reduce);
  requireSameMachine(machine, values.machine(), "reduceMax");
  detail::chargeTree(machine.counters().reduce, machine.grid(), 1, kWireBytes<T> + kWireBytes<int>,
                     std::is_floating_point_v<T>);
  Located<T> best;
  for (int pe = 0; pe < machine.size(); ++pe) {
    if (!machine.active(pe)) continue;
    detail::refuseNaN(machine, values[pe], pe, "reduceMax");
    if (best.pe < 0 || best.value < values[pe]) best = {values[pe], pe};
  }
  return best;
}

// The sum over the active PEs, added in row-major order from T{} (so the same bits every run).
template <class T>
T reduceAdd(MeshMachine& machine, const Plural<T>& values) {
  const HostTimer timer = machine.timeHost(machine.counters().reduce);
  requireSameMachine(machine, values.machine(), "reduceAdd");
  detail::chargeTree(machine.counters().reduce, machine.grid(), 1, kWireBytes<T>,
                     std::is_floating_point_v<T>);
  T sum{};
  for (int pe = 0; pe < machine.size(); ++pe)
    if (machine.active(pe)) sum = sum + values[pe];
  return sum;
}

}  // namespace radmesh::emu
