#pragma once
// The adaptive mapping of the paper's section 1.7: resize the plane's rows and columns from the
// projected patches so that every PE row and column gets a similar z-buffering load, keeping the
// mapping orthogonal and monotone (scan-directed load balancing, Biagioni & Prins). The loads are
// a mesh program: every projecting PE adds its description's width (height) to the pixel rows
// (columns) its bounding box spans, as a difference array built by add-combining router sends,
// and a parallel-prefix sum turns it into loads; the front end then places the cuts.
#include "emulator/pe_array.h"
#include "solver/backends/mesh/mesh_scan_conversion.h"

namespace radmesh {

// Throws OptionError when the plane has more pixel rows than the mesh has PEs.
PlaneMapping adaptiveMapping(emu::MeshMachine& machine, const MeshShot& shot,
                             const emu::PeArray<PatchRecord>& patchesOnPe,
                             int resolution);

}  // namespace radmesh
