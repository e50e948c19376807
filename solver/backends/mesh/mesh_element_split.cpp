#include "solver/backends/mesh/mesh_element_split.h"

#include <algorithm>
#include <vector>

#include "emulator/router.h"

namespace radmesh {

namespace {

// An element on its way to its PE after a split: its record, and the light it carries (its
// radiosity and this iteration's gain, RGB).
struct ElementInTransit {
  PatchRecord record;
  // routerSend compiles every combine; an element only ever arrives by Overwrite.
  friend ElementInTransit operator+(const ElementInTransit&, const ElementInTransit& b) { return b; }
  friend bool operator<(const ElementInTransit& a, const ElementInTransit& b) { return a.record.patch < b.record.patch; }
};

// Declared MP-1 work of a split (docs/emulator-cost-model.md): making an element from its parent
// (edge midpoints and centre, then the child's normal, area, centroid and projection frame, as
// solver/meshing/elements.cpp does) about 100 flops; its new PE and slot, 6 integer operations.
constexpr double kMakeElementFlops = 100.0;
constexpr double kPlaceElementIntOps = 6.0;

}  // namespace
}  // namespace radmesh

namespace radmesh::emu {
template <>
struct WireSize<radmesh::ElementInTransit> {
  static constexpr std::int64_t bytes = kWireBytes<radmesh::PatchRecord> + 6 * 4;
};
}  // namespace radmesh::emu

namespace radmesh {

void moveSplitElements(emu::MeshMachine& machine, const PatchLayout& before, const PatchLayout& after,
                       std::span<const int> origin, emu::PeArray<PatchRecord>& elementsOnPe) {
  // Per PE, the new elements made from the records it holds, in element order.
  std::vector<std::vector<int>> madeOn(machine.size());
  for (int e = 0; e < after.patches; ++e) madeOn[before.peOf(origin[e])].push_back(e);
  std::size_t rounds = 0;
  for (const std::vector<int>& made : madeOn) rounds = std::max(rounds, made.size());
  emu::PeArray<ElementInTransit> arrived(machine, "elements in transit");
  lay(arrived, after, [](int) { return ElementInTransit{}; });
  emu::Plural<ElementInTransit> element(machine, {}, "element made");
  emu::Plural<int> to(machine, 0, "its new PE"), slot(machine, 0, "its new slot");
  emu::Plural<bool> moves(machine, false, "element moves");
  for (std::size_t round = 0; round < rounds; ++round) {
    // Each PE makes its round's element; one that stays on its PE goes to its new slot in place.
    machine.compute({kMakeElementFlops, kPlaceElementIntOps}, [&](int pe) {
      moves[pe] = false;
      if (round >= madeOn[pe].size()) return;
      const int e = madeOn[pe][round];
      element[pe] = {PatchRecord{e}};
      to[pe] = after.peOf(e);
      slot[pe] = after.slotOf(e);
      moves[pe] = to[pe] != pe;
      if (!moves[pe]) arrived.at(pe, slot[pe]) = element[pe];
    });
    emu::ActiveScope scope(machine, moves);
    emu::routerSend(machine, arrived, element, to, slot, emu::Combine::Overwrite);
  }
  // Each PE copies what arrived into its element list, and the transit buffer is freed.
  elementsOnPe.clearAll();
  lay(elementsOnPe, after, [&](int e) { return arrived.at(after.peOf(e), after.slotOf(e)).record; });
  machine.chargeAlu({0.0, 2.0 * after.slotsPerPe()});
}

}  // namespace radmesh
