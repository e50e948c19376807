#include "solver/backends/mesh/mesh_scan_conversion.h"

#include <algorithm>
#include <optional>

#include "emulator/front_end.h"
#include "emulator/memory_ledger.h"
#include "emulator/router.h"
#include "emulator/xnet.h"

namespace radmesh {

namespace {

using emu::AluCost;
using emu::Direction;
using emu::Plural;

// Declared MP-1 work (docs/emulator-cost-model.md, assumption 6): the per-PE instruction counts
// of the loops below, estimated from the operations in solver/projection/projection.cpp and
// solver/projection/scan_conversion.cpp.
// Transform 4 vertices, normal and centroid into the shooter's frame (~80), clip against the
// near plane and divide (~40), edge functions, depth plane and bounding box (~80).
constexpr double kProjectFlopsPerPatch = 200.0;
// One (description, pixel) pair: up to 5 edge functions at 4 flops, the 1/depth plane (4) and
// the depth compare (4).
constexpr double kPixelTestFlops = 28.0;
// Decrement, test and keep-or-drop of one description in a spread step.
constexpr double kSpreadIntOpsPerItem = 4.0;
// Upper-left PE of a bounding box (two table look-ups and an index) and the strip length.
constexpr double kRouteIntOps = 8.0;

}  // namespace

MeshScanConversion::MeshScanConversion(emu::MeshMachine& machine, const std::vector<Patch>& shooters,
                                       const std::vector<Patch>& patches,
                                       const emu::PeArray<PatchRecord>& patchesOnPe,
                                       const ProjectionFace& face, double nearDepth)
    : machine_(machine),
      shooters_(shooters),
      patches_(patches),
      patchesOnPe_(patchesOnPe),
      face_(face),
      nearDepth_(nearDepth),
      rank_(depthTieRanks(patches)),
      descriptions_(machine, "patch descriptions"),
      forward_(machine, "descriptions to send on"),
      zBuffer_(machine, "item buffer pixels") {}

void MeshScanConversion::project(MeshShot& shot) {
  const int planes = static_cast<int>(shot.shooters.size());
  auto held = [&](int pe) { return machine_.holds(pe) ? patchesOnPe_.count(pe) : 0; };  // this process's PEs only
  shot.firstSlot.assign(machine_.size(), 0);
  for (int pe = 1; pe < machine_.size(); ++pe) shot.firstSlot[pe] = shot.firstSlot[pe - 1] + held(pe - 1);
  const int slots = shot.firstSlot.back() + held(machine_.size() - 1);
  shot.projections.assign(static_cast<std::size_t>(slots) * planes, PatchProjection{});
  // Each PE projects its own patches onto every plane of the shot into its own memory, so the PEs
  // can run on any number of host threads.
  const AluCost cost{kProjectFlopsPerPatch * planes * patchesOnPe_.maxCount(), 0.0};
  machine_.compute(cost, [&](int pe) {
    for (int slot = 0; slot < patchesOnPe_.count(pe); ++slot)
      for (int q = 0; q < planes; ++q) projectOne(shot, patchesOnPe_.at(pe, slot).patch, q, shot.projection(pe, slot, q));
  });
  listSetups(shot);
}

void MeshScanConversion::projectOne(const MeshShot& shot, int j, int q, PatchProjection& p) const {
  const int shooter = shot.shooters[q];
  if (j == shooter && &shooters_ == &patches_) return;
  // The projection stage's own functions, as the native back end calls them.
  const std::optional<LocalPolygon> local = inShooterView(shooters_[shooter], patches_[j]);
  if (!local) return;
  p.seenFromFront = local->seenFromFront();
  p.projected = setUpProjection(*local, face_, nearDepth_, j,
                                shotTieRank(rank_[j], p.seenFromFront, static_cast<int>(patches_.size())), p.setup);
}

void MeshScanConversion::listSetups(MeshShot& shot) const {
  const std::size_t planes = shot.shooters.size();
  shot.patches = patches_.size();
  shot.setups.assign(planes * shot.patches, nullptr);
  std::vector<char> here(shot.patches, 0);
  machine_.forEachPe([&](int pe) {
    for (int slot = 0; slot < patchesOnPe_.count(pe); ++slot) {
      const int j = patchesOnPe_.at(pe, slot).patch;
      here[j] = 1;
      for (std::size_t q = 0; q < planes; ++q)
        if (const PatchProjection& p = shot.projection(pe, slot, static_cast<int>(q)); p.projected)
          shot.setups[q * shot.patches + j] = &p.setup;
    }
  });
  shot.elsewhere.clear();
  if (!machine_.distributed()) return;
  shot.elsewhere.resize(planes * shot.patches);
  for (std::size_t j = 0; j < shot.patches; ++j)
    for (std::size_t q = 0; q < planes && !here[j]; ++q) {
      PatchProjection& p = shot.elsewhere[q * shot.patches + j];
      projectOne(shot, static_cast<int>(j), static_cast<int>(q), p);
      if (p.projected) shot.setups[q * shot.patches + j] = &p.setup;
    }
}

ScanDepths MeshScanConversion::scanConvert(const MeshShot& shot, MeshShotStats& stats) {
  const int patches = static_cast<int>(patches_.size());
  for (int passes = 1;; passes *= 2) {
    ScanDepths depths{std::vector<int>(machine_.size(), 0), std::vector<int>(machine_.size(), 0), passes};
    {
      PhaseClock clock(machine_, stats, "spread right, z-buffer");
      resetItemBuffers(shot);
    }
    try {
      for (int pass = 0; pass < passes; ++pass) {
        {
          PhaseClock clock(machine_, stats, "route (a)");
          routeToUpperLeft(shot, pass, passes, depths);
        }
        {
          PhaseClock clock(machine_, stats, "spread down (b)");
          spreadDown(depths);
        }
        PhaseClock clock(machine_, stats, "spread right, z-buffer");
        spreadRight(shot);
      }
      descriptions_.releaseAll();  // the next phase needs the room
      forward_.releaseAll();
      gatherDepths(depths);
      return depths;
    } catch (const emu::MemoryBudgetError&) {
      descriptions_.releaseAll();
      forward_.releaseAll();
      if (passes >= patches) throw;  // one patch per pass and still too big: nothing left to split
    }
  }
}

void MeshScanConversion::routeToUpperLeft(const MeshShot& shot, int pass, int passes, ScanDepths& depths) {
  const emu::PeGrid& grid = machine_.grid();
  descriptions_.releaseAll();  // each pass starts with the PEs' memory as the last one found it
  Plural<Description> message(machine_, {}, "outgoing description");
  Plural<int> destination(machine_, 0, "upper-left PE");
  Plural<bool> sends(machine_, false, "has a description");
  // SIMD: one router send per (plane, patch slot); PEs without that description sit it out.
  for (int q = 0; q < static_cast<int>(shot.shooters.size()); ++q)
    for (int slot = 0; slot < patchesOnPe_.maxCount(); ++slot) {
      machine_.chargeAlu({0.0, kRouteIntOps});
      machine_.forEachPe([&](int pe) {
        sends[pe] = false;
        if (slot >= patchesOnPe_.count(pe)) return;
        const PatchProjection& p = shot.projection(pe, slot, q);
        if (!p.projected || patchesOnPe_.at(pe, slot).patch % passes != pass) return;
        const PolygonSetup& s = p.setup;
        sends[pe] = true;
        message[pe] = {s.id, q, shot.mapping.rows.stepsToCover(s.rowBegin, s.rowEnd)};
        destination[pe] = grid.index(shot.mapping.rows.peOf(s.rowBegin),
                                     shot.mapping.columns.peOf(s.columnBegin));
      });
      emu::ActiveScope scope(machine_, sends);
      const emu::RouterStats routed = emu::routerSendAppend(machine_, descriptions_, message, destination);
      machine_.forEachPe([&](int pe) { depths.a[pe] += routed.arrivals[pe]; });
    }
}

void MeshScanConversion::spreadDown(ScanDepths& depths) {
  // What goes on down is counted first, so that every process reserves the longest list.
  int most = 0, mostAt = 0;
  machine_.forEachPe([&](int pe) {
    int going = 0;
    for (int i = 0; i < descriptions_.count(pe); ++i) going += descriptions_.at(pe, i).stepsLeft > 0;
    if (going > most) most = going, mostAt = pe;
  });
  forward_.reserveAcross(most, mostAt);
  machine_.forEachPe([&](int pe) {
    for (int i = 0; i < descriptions_.count(pe); ++i)
      if (descriptions_.at(pe, i).stepsLeft > 0) forward_.pushReserved(pe, i);
  });
  machine_.chargeAlu({0.0, kSpreadIntOpsPerItem * descriptions_.maxCount()});
  // One xnet step south per round: every PE keeps (accumulates) what reaches it, and sends on
  // what must go further.
  while (forward_.maxCount() > 0) {
    emu::xnetForward(machine_, descriptions_, forward_, Direction::S, 1);
    machine_.chargeAlu({0.0, kSpreadIntOpsPerItem * forward_.maxCount()});
    machine_.forEachPe([&](int pe) {
      const auto arrived = forward_.list(pe);
      int kept = 0;
      for (int index : arrived)
        if (--descriptions_.at(pe, index).stepsLeft > 0) arrived[kept++] = index;
      forward_.truncate(pe, kept);
    });
  }
  forward_.releaseAll();
  machine_.forEachPe([&](int pe) { depths.b[pe] += descriptions_.count(pe); });
}

void MeshScanConversion::resetItemBuffers(const MeshShot& shot) {
  rowsPerPe_ = shot.mapping.rows.maxPixelsPerPe();
  columnsPerPe_ = shot.mapping.columns.maxPixelsPerPe();
  const int length = static_cast<int>(shot.shooters.size()) * pixelsPerPlane();
  zBuffer_.releaseAll();  // an adaptive mapping sizes it anew each shot
  zBuffer_.reserve(length);
  machine_.forEachPe([&](int pe) {
    zBuffer_.clear(pe);
    for (int i = 0; i < length; ++i) zBuffer_.pushReserved(pe, ZEntry{});
  });
  machine_.chargeAlu({0.0, static_cast<double>(length)});
}

int MeshScanConversion::zBuffer(const MeshShot& shot, int pe, const Description& d) {
  const PolygonSetup& s = shot.setupOf(d);
  const int base = d.plane * pixelsPerPlane();
  const auto rows = shot.mapping.rows.pixelsOf(machine_.grid().row(pe));
  const auto columns = shot.mapping.columns.pixelsOf(machine_.grid().col(pe));
  int tests = 0;
  for (std::size_t a = 0; a < rows.size(); ++a) {
    const int row = rows[a];
    if (row < s.rowBegin || row >= s.rowEnd) continue;
    for (std::size_t b = 0; b < columns.size(); ++b) {
      const int column = columns[b];
      if (column < s.columnBegin || column >= s.columnEnd) continue;
      ++tests;
      if (!covers(s, column, row)) continue;  // inside the bounding box, outside the patch
      const double inverseDepth = inverseDepthAt(s, column, row);
      ZEntry& z = zBuffer_.at(pe, base + static_cast<int>(a) * columnsPerPe_ + static_cast<int>(b));
      if (z.item == ItemBuffer::kNone ||
          closer(inverseDepth, s.rank, z.inverseDepth, shot.setupOf({z.item, d.plane, 0}).rank))
        z = {s.id, inverseDepth};
    }
  }
  return tests;
}

template <class Steps>
int MeshScanConversion::zBufferAndKeep(const MeshShot& shot, int pe, Steps steps) {
  const auto list = descriptions_.list(pe);
  int kept = 0;
  int tests = 0;
  for (std::size_t i = 0; i < list.size(); ++i) {
    Description& d = list[i];
    tests += zBuffer(shot, pe, d);
    d.stepsLeft = steps(d);
    if (d.stepsLeft <= 0) continue;
    if (static_cast<std::size_t>(kept) != i) list[kept] = d;
    ++kept;
  }
  descriptions_.truncate(pe, kept);
  return tests;
}

void MeshScanConversion::zBufferStep(const MeshShot& shot, bool first) {
  // Each PE runs through its own (description, pixel) pairs, the loop flattened, so the SIMD time
  // is the most pairs any PE has, not descriptions times pixels.
  const int most = descriptions_.maxCount();
  pixelTests_.assign(machine_.size(), 0);
  machine_.forEachActive(kPixelTestFlops * most, [&](int pe) {
    if (first) {
      pixelTests_[pe] = zBufferAndKeep(shot, pe, [&](const Description& d) {
        const PolygonSetup& s = shot.setupOf(d);
        return shot.mapping.columns.stepsToCover(s.columnBegin, s.columnEnd);
      });
    } else {
      pixelTests_[pe] = zBufferAndKeep(shot, pe, [](const Description& d) { return d.stepsLeft - 1; });
    }
  });
  const auto pairs = emu::mostOverProcesses(machine_, *std::max_element(pixelTests_.begin(), pixelTests_.end()));
  machine_.chargeAlu({kPixelTestFlops * pairs, kSpreadIntOpsPerItem * most});
}

void MeshScanConversion::spreadRight(const MeshShot& shot) {
  // Every PE z-buffers the strip pieces it holds; they then travel east one PE per step, each PE
  // z-buffering what passes through it without keeping it (section 1.5).
  zBufferStep(shot, true);
  emu::Plural<bool> busy(machine_, false, "has arrivals");
  while (descriptions_.maxCount() > 0) {
    emu::xnetShift(machine_, descriptions_, descriptions_, Direction::E, 1);
    machine_.forEachPe([&](int pe) { busy[pe] = descriptions_.count(pe) > 0; });
    emu::ActiveScope scope(machine_, busy);
    zBufferStep(shot, false);
  }
}

void MeshScanConversion::gatherDepths(ScanDepths& depths) const {
  if (!machine_.distributed()) return;  // one process counted every PE
  struct Depth {
    int pe = 0;
    int a = 0;
    int b = 0;
  };
  std::vector<Depth> held;
  machine_.forEachPe([&](int pe) { held.push_back({pe, depths.a[pe], depths.b[pe]}); });
  for (const Depth& d : emu::gatherByPe(machine_, std::move(held))) depths.a[d.pe] = d.a, depths.b[d.pe] = d.b;
}

ItemBuffer MeshScanConversion::gatherItemBuffer(const MeshShot& shot, int plane) const {
  ItemBuffer buffer(face_.width, face_.height);
  struct Pixel {
    int pe = 0;
    int index = 0;  // in the buffer
    ZEntry z;
  };
  std::vector<Pixel> held;
  machine_.forEachPe([&](int pe) {
    const auto rows = shot.mapping.rows.pixelsOf(machine_.grid().row(pe));
    const auto columns = shot.mapping.columns.pixelsOf(machine_.grid().col(pe));
    for (std::size_t a = 0; a < rows.size(); ++a)
      for (std::size_t b = 0; b < columns.size(); ++b)
        held.push_back({pe, buffer.index(columns[b], rows[a]),
                        zBuffer_.at(pe, plane * pixelsPerPlane() + static_cast<int>(a) * columnsPerPe_ +
                                            static_cast<int>(b))});
  });
  for (const Pixel& p : emu::gatherByPe(machine_, std::move(held))) {
    buffer.items[p.index] = p.z.item;
    buffer.inverseDepth[p.index] = p.z.inverseDepth;
  }
  return buffer;
}

}  // namespace radmesh
