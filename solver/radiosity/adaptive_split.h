#pragma once
// Where adaptive subdivision (--subdivide adaptive, Cohen, Chen, Wallace & Greenberg 1988) splits
// an element: the gradient criterion (its light differs too much from a neighbour's) and the shadow
// criterion (a shooter's visibility changes across it). Pure functions of the geometry, the rows
// and the radiosities: the solver (progressive_solver.cpp) applies them after each iteration.
#include <vector>

#include "solver/formfactors/form_factor_row.h"
#include "solver/meshing/occluders.h"
#include "solver/meshing/elements.h"

namespace radmesh {

// Only shots carrying at least this fraction of the first shot's power are checked for shadow
// edges: weaker shooters cast soft shadows the gradient criterion sees, and the check costs rays.
inline constexpr double kShadowShotFraction = 0.05;

// Each element's neighbours, ascending: the elements of the same scene polygon whose bounding
// boxes touch its own (sharing an edge or a corner, or, between triangles, lying close), and the
// elements of other polygons sharing part of an edge with it where light passes between the two
// (coplanar, or a concave fold such as a wall meeting the floor; not a convex fold such as a table's
// edge, whose step is its outline, nor faces back to back). Kept across splits with what finds them:
// every pair whose (slightly grown) bounding boxes overlap, of which the neighbours are some, and
// the boxes. splitAdjacency after splitElements (origin and split as it has them) gives bit for bit
// what elementAdjacency gives from scratch, looking only at the split elements' old overlaps: the
// split rounds of a large scene (the corridor's 24,000 elements) spent a third of the solve finding
// every element's neighbours anew.
struct ElementAdjacency {
  std::vector<AxisBox> boxes;
  std::vector<std::vector<int>> overlapping;  // ascending
  std::vector<std::vector<int>> neighbours;   // ascending
};
ElementAdjacency elementAdjacency(const Elements& elements);
void splitAdjacency(ElementAdjacency& adjacency, const Elements& elements, const std::vector<int>& origin,
                    const std::vector<char>& split);

// Whether an element is long enough to split: its children (half its edges) no shorter than
// minElementM along their longest edge.
bool splittable(const Patch& element, double minElementM);

// The gradient criterion: marks (split[e] = 1) both elements of every neighbouring pair whose
// reflected radiosities (W/m^2 summed over RGB) differ by more than `contrast` times the brightest
// element's (contrastStep and stepTooLarge, solver/meshing/gradient_criterion.h). Marks only
// splittable elements.
void markContrast(const Elements& elements, const std::vector<std::vector<int>>& neighbours,
                  const std::vector<double>& reflected, double contrast, double minElementM,
                  std::vector<char>& split);

// The shadow criterion for receiver r of a row of `shooter`: when the row shows the element
// partly hidden (form factor below 95 % of the unoccluded point-to-polygon one), marks it if it
// is splittable and its corners disagree on seeing a point of the shooter (its corners or its
// centroid). Touches split[row.receivers[r]] alone; returns the rays it cast (segmentBlocked calls).
int markShadowEdge(const FormFactorRow& row, std::size_t r, const Patch& shooter, const Elements& elements,
                   const Occluders& occluders, double minElementM, std::vector<char>& split);

// Declared MP-1 work of markShadowEdge (docs/emulator-cost-model.md) for the mesh back end: the
// unoccluded form factor of an element's 4 corners (4 edges at about 40 flops) and the compare;
// a ray's box and plane-crossing test against one patch (about 30 flops).
inline constexpr double kShadowTestFlops = 170.0;
inline constexpr double kRayPatchFlops = 30.0;

}  // namespace radmesh
