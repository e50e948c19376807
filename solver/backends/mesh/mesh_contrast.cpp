#include "solver/backends/mesh/mesh_contrast.h"

#include <algorithm>
#include <limits>

#include "emulator/active_mask.h"
#include "emulator/front_end.h"
#include "emulator/reduce.h"
#include "emulator/router.h"
#include "solver/meshing/gradient_criterion.h"

namespace radmesh {

namespace {

// A neighbour's light on its way to an element's PE.
struct NeighbourLight {
  int element = -1;  // the element it is for
  double light = 0.0;
};

// A mark the front end reads from a PE.
struct Mark {
  int pe = 0;
  int element = 0;
};

}  // namespace

void markContrastOnMesh(emu::MeshMachine& m, const emu::PeArray<PatchRecord>& elementsOnPe, const PatchLayout& layout,
                        const std::vector<std::vector<int>>& neighbours, const std::vector<double>& reflected,
                        double contrast, const std::function<bool(int)>& canSplit, std::vector<char>& split) {
  const double slots = layout.slotsPerPe();
  emu::Plural<double> brightestOnPe(m, std::numeric_limits<double>::lowest(), "brightest element");
  m.compute({kReflectedFlops * slots, slots}, [&](int pe) {
    for (const PatchRecord& e : elementsOnPe.list(pe)) brightestOnPe[pe] = std::max(brightestOnPe[pe], reflected[e.patch]);
  });
  const double step = contrastStep(contrast, emu::reduceMax(m, brightestOnPe).value);

  // Round r: each PE sends the light of its r-th (element, neighbour) pair to the neighbour's PE.
  std::vector<std::vector<NeighbourLight>> pairs(m.size());
  std::int64_t rounds = 0;
  m.forEachPe([&](int pe) {
    for (const PatchRecord& e : elementsOnPe.list(pe))
      for (int n : neighbours[e.patch]) pairs[pe].push_back({n, reflected[e.patch]});
    rounds = std::max(rounds, static_cast<std::int64_t>(pairs[pe].size()));
  });
  rounds = emu::mostOverProcesses(m, rounds);
  emu::PeArray<NeighbourLight> arrived(m, "neighbours' light");
  emu::Plural<NeighbourLight> message(m, {}, "element's light");
  emu::Plural<int> to(m, 0, "neighbour's PE");
  emu::Plural<bool> sends(m, false, "has a pair left");
  for (std::int64_t r = 0; r < rounds; ++r) {
    m.compute({0.0, kContrastSendIntOps}, [&](int pe) {
      sends[pe] = r < static_cast<std::int64_t>(pairs[pe].size());
      if (!sends[pe]) return;
      message[pe] = pairs[pe][r];
      to[pe] = layout.peOf(message[pe].element);
    });
    emu::ActiveScope scope(m, sends);
    emu::routerSendAppend(m, arrived, message, to);
  }

  // Each PE compares, SIMD, as many arrivals as the busiest PE holds.
  std::int64_t most = 0;
  m.forEachPe([&](int pe) { most = std::max(most, static_cast<std::int64_t>(arrived.count(pe))); });
  most = emu::mostOverProcesses(m, most);
  std::vector<std::vector<Mark>> markedOn(m.size());
  m.compute({kContrastCompareFlops * most, kContrastFindIntOps * most}, [&](int pe) {
    for (const NeighbourLight& a : arrived.list(pe))
      if (stepTooLarge(reflected[a.element], a.light, step) && canSplit(a.element)) markedOn[pe].push_back({pe, a.element});
  });
  std::vector<Mark> marked;
  m.forEachPe([&](int pe) { marked.insert(marked.end(), markedOn[pe].begin(), markedOn[pe].end()); });
  for (const Mark& mark : emu::gatherByPe(m, std::move(marked))) split[mark.element] = 1;
}

}  // namespace radmesh
