#pragma once
// The gradient criterion of adaptive subdivision (solver/radiosity/adaptive_split.h,
// markContrast) on the machine that holds the elements: each PE's brightest element and one
// reduceMax give the step; each element's light goes by the router to the PEs of its neighbours
// (neighbour lists are symmetric, so what arrives at an element is its neighbours' light); each PE
// compares what arrived with its own elements' light. The front end reads the marks back.
#include <functional>
#include <vector>

#include "emulator/mesh_machine.h"
#include "emulator/pe_array.h"
#include "solver/backends/mesh/mesh_form_factors.h"
#include "solver/backends/mesh/mesh_scan_conversion.h"

namespace radmesh {

// Declared MP-1 work (docs/emulator-cost-model.md): an element's reflected light from its RGB
// radiosity and emittance, 6 flops; a received light's compare with its element's (a difference,
// its magnitude and the compare), 3 flops, and finding that element in the PE's list, 2 integer
// operations; naming a pair's destination, 2.
inline constexpr double kReflectedFlops = 6.0;
inline constexpr double kContrastCompareFlops = 3.0;
inline constexpr double kContrastFindIntOps = 2.0;
inline constexpr double kContrastSendIntOps = 2.0;

// Marks split[e] = 1 for every element e (laid on the PEs by `layout`, held in `elementsOnPe`)
// with a neighbour whose reflected light differs from its own by more than contrast times the
// brightest element's, where canSplit(e): what markContrast marks, found on the PEs.
void markContrastOnMesh(emu::MeshMachine& machine, const emu::PeArray<PatchRecord>& elementsOnPe,
                        const PatchLayout& layout, const std::vector<std::vector<int>>& neighbours,
                        const std::vector<double>& reflected, double contrast,
                        const std::function<bool(int)>& canSplit, std::vector<char>& split);

}  // namespace radmesh
