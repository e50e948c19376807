#pragma once
// Elements moving to their PEs after an adaptive split: each PE makes the elements cut from the
// records it holds, one a round, and routes each to the PE and slot the new layout gives it.
#include <span>

#include "emulator/mesh_machine.h"
#include "emulator/pe_array.h"
#include "solver/backends/mesh/mesh_form_factors.h"
#include "solver/backends/mesh/mesh_scan_conversion.h"

namespace radmesh {

// elementsOnPe, laid out by `before`, becomes the elements laid out by `after`; element e is cut
// from the record of receiver origin[e] of `before`.
void moveSplitElements(emu::MeshMachine& machine, const PatchLayout& before, const PatchLayout& after,
                       std::span<const int> origin, emu::PeArray<PatchRecord>& elementsOnPe);

}  // namespace radmesh
