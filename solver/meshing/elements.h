#pragma once
// Substructuring (Cohen, Greenberg, Immel & Brock 1986): patches shoot, elements receive. Each
// patch is cut into elements, the receivers of its light; a patch's radiosity is the area mean of
// its elements'. Elements are Patches themselves (geometry, normal, frame, material and polygon of
// their patch), so that every projection and back end takes them as receivers unchanged.
#include <cstddef>
#include <string>
#include <vector>

#include "solver/meshing/patch.h"
#include "solver/scene/solve_options.h"

namespace radmesh {

// Split elements (--subdivide adaptive): splitElements replaces an element, in place in the list,
// by its four children, so elements stay listed patch by patch and a patch's elements tile it
// exactly (no overlap, no gap). An element's corners are its Patch::vertices, counter-clockwise:
// - a quad (v0 v1 v2 v3) splits at its edge midpoints m01 m12 m23 m30 and centre c = (m01 + m23) / 2
//   into (v0 m01 c m30), (m01 v1 m12 c), (c m12 v2 m23), (m30 c m23 v3);
// - a triangle (v0 v1 v2) into (v0 m01 m20), (m01 v1 m12), (m20 m12 v2) and the middle (m12 m20 m01).
// A midpoint is (a + b) / 2 of the edge's two corners, which rounds the same from either side, so
// an element split next to an unsplit one puts a vertex exactly on the unsplit one's edge (a
// T-vertex): the display mesh finds those where an element's neighbour has a higher level.
struct Elements {
  std::vector<Patch> elements;
  std::vector<int> patchOf;  // per element: the patch it was cut from
  std::vector<int> first;    // per patch p, its elements are [first[p], first[p + 1]); patches + 1 entries
  std::vector<int> level;    // per element: how many splits made it from its first element (0: not split)
};

// The cuts per edge that make a patch's elements no longer than minElementM along any edge: its
// longest edge over minElementM, rounded up (1: the patch is its own element). minElementM 0: 2,
// every patch cut once along each edge (four elements).
int elementCuts(const Patch& patch, double minElementM);

// How many elements subdivideUniform makes: the sum of the patches' elementCuts squared.
double countElements(const std::vector<Patch>& patches, double minElementM);

// The most elements a solve may make: --subdivide uniform's count, and adaptive subdivision's when
// every element split down to --min-element.
inline constexpr std::size_t kMaxElements = 20'000'000;
// What an element takes at a solve's peak, writing its bake (measured: 2.37 M uniform elements of
// the Cornell box peaked at 2.3 GB with --out).
inline constexpr std::size_t kPeakBytesPerElement = 1024;
// How many elements may be made, and what set that number, for the refusal to say.
struct ElementLimit {
  std::size_t count = kMaxElements;
  std::string why;  // "" for a limit given as it is
};
// kMaxElements, or fewer where they would take more than half of `memoryBytes` (usableMemoryBytes;
// 0: unknown) at their peak: a solve is refused up front rather than killed by the system midway.
ElementLimit elementLimit(std::size_t memoryBytes = usableMemoryBytes());

// Throws OptionError for a minElementM that is not finite and at least 0, or for which
// countElements exceeds limit.count; `what` says what the elements come from in the message ("would
// cut", "could let adaptive subdivision split"). Returns that count.
double checkElementCount(const std::vector<Patch>& patches, double minElementM, const ElementLimit& limit,
                         const std::string& what);

// checkElementCount for a solve's subdivision: uniform's elements, or with `adaptive` every element
// adaptive subdivision could make. That count bounds it: an element splits only while half its
// longest edge is at least minElementM, and each split halves the longest edge at least (a child's
// edges are halves of its parent's edges or of a midline, no longer than the parent's longest), so
// a patch of longest edge L ends in at most (L / minElementM)^2 elements, its elementCuts squared.
void checkElementBudget(const std::vector<Patch>& patches, bool adaptive, double minElementM);

// Every patch cut n ways per edge (n = elementCuts): a convex quad into the n x n grid of its
// bilinear parameterisation (straight lines joining points evenly spaced on opposite edges), a
// triangle into n^2 triangles (n = 2: the four-way split). Elements keep their patch's
// orientation and are listed patch by patch. Throws OptionError for a minElementM that is not
// finite and at least 0, or that would make more than limit.count elements.
Elements subdivideUniform(const std::vector<Patch>& patches, double minElementM,
                          const ElementLimit& limit = elementLimit());

// Every patch its own single element, level 0: where adaptive subdivision starts.
Elements patchesAsElements(const std::vector<Patch>& patches);

// The longest edge of a patch or element, metres.
double longestEdge(const Patch& patch);

// Splits the elements marked in `split` (one flag per element) into four children each, in place
// (see Elements above). Returns, per element after the split, the element it was or came from.
std::vector<int> splitElements(Elements& elements, const std::vector<char>& split);
// Per element before that split, its index after it, or -1 for one that split.
std::vector<int> newIndices(const std::vector<int>& origin, const std::vector<char>& split);

// The elements adaptive subdivision split `patches` into, from their levels alone (a checkpoint
// keeps those): a patch's leaves in order, with their levels, name its split tree, since splitting
// puts an element's children where it was; an element's corners depend on its tree alone, not on
// when it split. Throws std::invalid_argument for levels that tile no patch (each patch's leaves
// must cover it exactly: those of level L a quarter of their level L - 1 parent), or above 31.
Elements splitToLevels(const std::vector<Patch>& patches, const std::vector<int>& levels);

}  // namespace radmesh
