#pragma once
// Substructuring's shot without projecting the elements (--element-rows share): the item buffer
// holds the patches, and each patch's form factor is shared among its elements in proportion to
// their analytic point-to-polygon form factors (exact without occlusion; Baum, Rushmeier & Winget
// 1989 take visibility from the projection the same way), each times the fraction of its pixels
// that show the patch. A patch the item buffer shows whole shares by the closed forms alone, so a
// shot costs the patches' projection plus one closed form per element of the patches it sees,
// whatever the elements elsewhere; only a patch partly hidden (a shadow edge crosses it) walks its
// elements' pixels. An element's row entry is smooth where the light is, rather than a count of
// pixel centres, and every patch's elements together receive exactly the patch's form factor, so
// the shots, the ledger and the patches' answer are those of the patch projection.
#include <span>
#include <vector>

#include "solver/formfactors/sub_pixel_receivers.h"
#include "solver/meshing/elements.h"
#include "parallel/thread_pool.h"

namespace radmesh {

// What one projection of the patches (shot.patches, whose elements are `elements`) gave per patch.
struct PatchShot {
  std::span<const double> formFactors;  // the row entries
  std::span<const char> seenFromFront;
  std::span<const long long> coveredPixels;  // pixel centres its projection covers
  std::span<const long long> shownPixels;    // those showing it
  std::span<const unsigned> facesReached;    // bit f: its projection reaches face f
};

// Fills, per element, its form factor and whether the shooter sees its front (its patch's side).
void shareAmongElements(const ProjectedShot& shot, double nearDepth, const PatchShot& patches, const Elements& elements,
                        ThreadPool& pool, std::vector<double>& elementFormFactors,
                        std::vector<char>& elementSeenFromFront);

}  // namespace radmesh
