#pragma once
// Substructuring (Cohen, Greenberg, Immel & Brock 1986): patches shoot, elements receive. Each
// patch is cut into elements, the receivers of its light; a patch's radiosity is the area mean of
// its elements'. Elements are Patches themselves (geometry, normal, frame, material and polygon of
// their patch), so that every projection and back end takes them as receivers unchanged.
#include <cstddef>
#include <vector>

#include "solver/meshing/patch.h"

namespace radmesh {

struct Elements {
  std::vector<Patch> elements;
  std::vector<int> patchOf;  // per element: the patch it was cut from
  std::vector<int> first;    // per patch p, its elements are [first[p], first[p + 1]); patches + 1 entries
};

// The cuts per edge that make a patch's elements no longer than minElementM along any edge: its
// longest edge over minElementM, rounded up (1: the patch is its own element). minElementM 0: 2,
// every patch cut once along each edge (four elements).
int elementCuts(const Patch& patch, double minElementM);

// How many elements subdivideUniform makes: the sum of the patches' elementCuts squared.
double countElements(const std::vector<Patch>& patches, double minElementM);

// Every patch cut n ways per edge (n = elementCuts): a convex quad into the n x n grid of its
// bilinear parameterisation (straight lines joining points evenly spaced on opposite edges), a
// triangle into n^2 triangles (n = 2: the four-way split). Elements keep their patch's
// orientation and are listed patch by patch. Throws OptionError for a minElementM that is not
// finite and at least 0, or that would make more than maxElements elements.
Elements subdivideUniform(const std::vector<Patch>& patches, double minElementM,
                          std::size_t maxElements = 20'000'000);

}  // namespace radmesh
