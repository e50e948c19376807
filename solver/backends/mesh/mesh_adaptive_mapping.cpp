#include "solver/backends/mesh/mesh_adaptive_mapping.h"

#include <string>

#include "emulator/front_end.h"
#include "emulator/router.h"
#include "emulator/scan.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

namespace {

using emu::Plural;

// Loads per pixel along one axis: PE p stands for pixel p.
std::vector<double> axisLoads(emu::MeshMachine& m, const MeshShot& shot,
                              const emu::PeArray<PatchRecord>& patchesOnPe,
                              int resolution, bool alongRows) {
  Plural<double> difference(m, 0.0, "load differences");
  Plural<double> weight(m, 0.0, "description weight");
  Plural<int> to(m, 0, "pixel PE");
  Plural<bool> sends(m, false, "has a description");
  for (int q = 0; q < static_cast<int>(shot.shooters.size()); ++q)
    for (int slot = 0; slot < patchesOnPe.maxCount(); ++slot)
      for (int edge = 0; edge < 2; ++edge) {  // +weight where the box begins, -weight past its end
        m.chargeAlu({1.0, 4.0});
        m.forEachPe([&](int pe) {
          sends[pe] = false;
          if (slot >= patchesOnPe.count(pe)) return;
          const PatchProjection& p = shot.projection(pe, slot, q);
          if (!p.projected) return;
          const PolygonSetup& s = p.setup;
          const int begin = alongRows ? s.rowBegin : s.columnBegin;
          const int end = alongRows ? s.rowEnd : s.columnEnd;
          const int across = alongRows ? s.columnEnd - s.columnBegin : s.rowEnd - s.rowBegin;
          if (edge == 1 && end >= resolution) return;
          sends[pe] = true;
          to[pe] = edge == 0 ? begin : end;
          weight[pe] = edge == 0 ? across : -across;
        });
        emu::ActiveScope scope(m, sends);
        emu::routerSend(m, difference, weight, to, emu::Combine::Add);
      }
  Plural<double> load(m, 0.0, "pixel load");
  Plural<bool> pixel(m, false, "stands for a pixel"), noStarts(m, false, "segment starts");
  m.forEachPe([&](int pe) { pixel[pe] = pe < resolution; });
  {
    emu::ActiveScope scope(m, pixel);
    emu::segmentedScan(m, load, difference, noStarts, emu::ScanKind::Inclusive);
  }
  struct PixelLoad {
    int pe = 0;
    double load = 0.0;
  };
  std::vector<PixelLoad> held;
  m.forEachPe([&](int pe) {
    if (pe < resolution) held.push_back({pe, load[pe]});
  });
  std::vector<double> loads(resolution, 0.0);
  for (const PixelLoad& l : emu::gatherByPe(m, std::move(held))) loads[l.pe] = l.load;
  return loads;
}

}  // namespace

PlaneMapping adaptiveMapping(emu::MeshMachine& m, const MeshShot& shot,
                             const emu::PeArray<PatchRecord>& patchesOnPe,
                             int resolution) {
  if (resolution > m.size())
    throw OptionError("--mapping adaptive measures loads with one PE per pixel row, so it needs a "
                      "resolution of at most " + std::to_string(m.size()) + " on this mesh; use a lower "
                      "--resolution or another --mapping");
  const auto rowLoads = axisLoads(m, shot, patchesOnPe, resolution, true);
  const auto columnLoads = axisLoads(m, shot, patchesOnPe, resolution, false);
  return {AxisMapping::fromLoads(columnLoads, m.grid().cols), AxisMapping::fromLoads(rowLoads, m.grid().rows)};
}

}  // namespace radmesh
