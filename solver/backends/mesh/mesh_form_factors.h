#pragma once
// The paper's form-factor phase (section 1.5) on the mesh: a surviving description of patch j at
// pixel q must add the pixel's delta form factor to F_ij. Done independently of how patches lie
// on the plane: one sort of (item, delta form factor) pairs over the mesh, a segmented
// parallel-prefix sum, and one router send (add-combining) from the last pixel of each item's
// run to the PE that holds patch j.
#include <vector>

#include "emulator/pe_array.h"
#include "solver/backends/mesh/mesh_scan_conversion.h"
#include "solver/projection/projection_surface.h"

namespace radmesh {

// Patches lie on the PEs cyclically: patch j on PE j mod PEs, in slot j div PEs (section 1.5:
// "spread out equally over the PE-array").
struct PatchLayout {
  int patches = 0;
  int pes = 0;
  int slotsPerPe() const { return (patches + pes - 1) / pes; }
  int peOf(int patch) const { return patch % pes; }
  int slotOf(int patch) const { return patch / pes; }
};

// Fills `onPe` with of(j) for every item j of the layout, at its PE and slot: on a machine split
// over processes, those of this process's PEs; PE 0 holds the most, which every PE reserves.
template <class T, class Of>
void lay(emu::PeArray<T>& onPe, const PatchLayout& layout, Of of) {
  onPe.reserve(layout.slotsPerPe());
  for (int j = 0; j < layout.patches; ++j)
    if (onPe.machine().holds(layout.peOf(j))) onPe.push(layout.peOf(j), of(j));
}

// Per plane of the shot, per patch: the summed delta form factors of the pixels showing it.
std::vector<std::vector<double>> meshFormFactors(emu::MeshMachine& machine,
                                                 const MeshScanConversion& scan,
                                                 const MeshShot& shot,
                                                 const ProjectionSurface& surface,
                                                 const PatchLayout& layout);

}  // namespace radmesh
