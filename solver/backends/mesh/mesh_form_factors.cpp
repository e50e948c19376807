#include "solver/backends/mesh/mesh_form_factors.h"

#include <limits>

#include "emulator/front_end.h"
#include "emulator/mesh_sort.h"
#include "emulator/router.h"
#include "emulator/scan.h"
#include "emulator/xnet.h"

namespace radmesh {

namespace {

using emu::Direction;
using emu::PeArray;
using emu::Plural;

constexpr int kNoItem = std::numeric_limits<int>::max();  // sorts after every item
// Per pixel: look up its delta form factor and build the key (index arithmetic, one load).
constexpr double kPairIntOps = 6.0;
// Per slot: compare with the neighbouring key, set the flag.
constexpr double kFlagIntOps = 3.0;

int nextPowerOfTwo(int x) {
  int p = 1;
  while (p < x) p *= 2;
  return p;
}

// Each PE's value from its predecessor in row-major order (towards = E, SE) or its successor
// (towards = W, NW): within a row the neighbour is one column over; at the row's edge it is
// diagonal across the wrap-around, the previous or next row's far end.
void rowMajorNeighbour(emu::MeshMachine& m, Plural<int>& dst, const Plural<int>& src, bool fromPredecessor) {
  const int lastColumn = m.grid().cols - 1;
  const int edgeColumn = fromPredecessor ? 0 : lastColumn;
  Plural<bool> atEdge(m, false, "at the row's edge");
  m.forEachPe([&](int pe) { atEdge[pe] = m.grid().col(pe) == edgeColumn; });
  emu::ActiveScope scope(m, atEdge);
  emu::xnetShift(m, dst, src, fromPredecessor ? Direction::SE : Direction::NW, 1);
  scope.elseBranch();
  emu::xnetShift(m, dst, src, fromPredecessor ? Direction::E : Direction::W, 1);
}

}  // namespace

std::vector<std::vector<double>> meshFormFactors(emu::MeshMachine& m, const MeshScanConversion& scan,
                                                 const MeshShot& shot, const ProjectionSurface& surface,
                                                 const PatchLayout& layout) {
  const int planes = static_cast<int>(shot.shooters.size());
  const int n = layout.patches;
  const int perPe = nextPowerOfTwo(planes * scan.pixelsPerPlane());
  // The plane's delta form factors depend on its resolution alone: every process holds them.
  const std::vector<double>& deltaFormFactor = surface.deltaFormFactors[0];
  const int width = surface.faces[0].width;

  // Every PE lists (item, delta form factor) for its pixels; empty pixels and padding sort last.
  PeArray<int> keys(m, perPe, kNoItem, "sort keys");
  PeArray<double> values(m, perPe, 0.0, "delta form factors");
  m.compute({0.0, kPairIntOps * perPe}, [&](int pe) {
    const auto rows = shot.mapping.rows.pixelsOf(m.grid().row(pe));
    const auto columns = shot.mapping.columns.pixelsOf(m.grid().col(pe));
    for (int q = 0; q < planes; ++q)
      for (std::size_t a = 0; a < rows.size(); ++a)
        for (std::size_t b = 0; b < columns.size(); ++b) {
          const int slot = q * scan.pixelsPerPlane() + static_cast<int>(a) * scan.columnsPerPe() + static_cast<int>(b);
          const ZEntry& z = scan.itemBuffers().at(pe, slot);
          if (z.item == ItemBuffer::kNone) continue;
          keys.at(pe, slot) = q * n + z.item;
          values.at(pe, slot) = deltaFormFactor[static_cast<std::size_t>(rows[a]) * width + columns[b]];
        }
  });
  emu::sortPairs(m, keys, values);

  // Runs of equal keys are segments; a run may cross from one PE to the next in row-major order.
  Plural<int> firstKey(m, kNoItem, "first key"), lastKey(m, kNoItem, "last key");
  m.forEachPe([&](int pe) { firstKey[pe] = keys.at(pe, 0), lastKey[pe] = keys.at(pe, perPe - 1); });
  Plural<int> predecessorKey(m, kNoItem, "predecessor's last key"), successorKey(m, kNoItem, "successor's first key");
  rowMajorNeighbour(m, predecessorKey, lastKey, true);
  rowMajorNeighbour(m, successorKey, firstKey, false);
  PeArray<bool> starts(m, perPe, false, "segment starts");
  m.chargeAlu({0.0, kFlagIntOps * perPe});
  m.forEachPe([&](int pe) {
    for (int t = 0; t < perPe; ++t) {
      const int before = t > 0 ? keys.at(pe, t - 1) : (pe > 0 ? predecessorKey[pe] : kNoItem);
      starts.at(pe, t) = keys.at(pe, t) != before;
    }
  });
  PeArray<double> sums(m, "segment sums");
  emu::segmentedScan(m, sums, values, starts, emu::ScanKind::Inclusive);

  // The last pixel of each run sends its sum to the patch's PE: one router send per slot.
  PeArray<double> formFactors(m, planes * layout.slotsPerPe(), 0.0, "form factors");
  Plural<double> sum(m, 0.0, "run sum");
  Plural<int> toPe(m, 0, "patch PE"), toSlot(m, 0, "patch slot");
  Plural<bool> sends(m, false, "ends a run");
  for (int t = 0; t < perPe; ++t) {
    m.chargeAlu({0.0, kFlagIntOps});
    m.forEachPe([&](int pe) {
      const int key = keys.at(pe, t);
      const int after = t + 1 < perPe ? keys.at(pe, t + 1) : (pe + 1 < m.size() ? successorKey[pe] : kNoItem);
      sends[pe] = key != kNoItem && key != after;
      if (!sends[pe]) return;
      const int patch = key % n;
      sum[pe] = sums.at(pe, t);
      toPe[pe] = layout.peOf(patch);
      toSlot[pe] = key / n * layout.slotsPerPe() + layout.slotOf(patch);
    });
    emu::ActiveScope scope(m, sends);
    emu::routerSend(m, formFactors, sum, toPe, toSlot, emu::Combine::Add);
  }

  // The front end reads each patch's form factors from its PE.
  struct Read {
    int pe = 0;
    int plane = 0;
    int patch = 0;
    double formFactor = 0.0;
  };
  std::vector<Read> held;
  for (int q = 0; q < planes; ++q)
    for (int j = 0; j < n; ++j)
      if (m.holds(layout.peOf(j)))
        held.push_back({layout.peOf(j), q, j, formFactors.at(layout.peOf(j), q * layout.slotsPerPe() + layout.slotOf(j))});
  std::vector<std::vector<double>> result(planes, std::vector<double>(n, 0.0));
  for (const Read& r : emu::gatherByPe(m, std::move(held))) result[r.plane][r.patch] = r.formFactor;
  return result;
}

}  // namespace radmesh
