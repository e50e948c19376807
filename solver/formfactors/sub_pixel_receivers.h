#pragma once
// Receivers smaller than a pixel, or narrower than four. A pixel centre either misses such a patch
// (it gets nothing) or hits it (it gets the whole pixel's delta form factor): the aliasing of the
// paper's section 1.6, which for a patch 1e-6 the size of its neighbour makes its radiosity 0 or
// absurd, and which for a sliver (a wall's 0.1 m strip between a grid line and a door's top) moves
// with the resolution alike along the whole strip: a fifth dark at 96², an eighth bright at 128². Such a
// patch gets instead the analytic point-to-polygon form factor (Baum, Rushmeier & Winget 1989:
// analytic form factors, visibility from the projection), times the fraction of the pixel centres
// it covers that show it; one covering none is seen where no patch crosses the segment from the
// shooter to its centroid (an exact test: the pixel its centroid falls in may show a surface
// beside the one that hides it). The row is then rescaled to the total the pixels caught, so no power is created
// or lost; the rescale is close to 1 since such patches carry little of it.
#include <span>
#include <vector>

#include "solver/meshing/occluders.h"
#include "solver/projection/item_buffer.h"
#include "solver/meshing/patch.h"
#include "solver/projection/projection_surface.h"
#include "parallel/thread_pool.h"

namespace radmesh {

inline constexpr double kSubPixelAreaPixels = 1.0;  // projected area below which a patch is refined
inline constexpr double kThinWidthPixels = 4.0;     // so is one narrower than this (PolygonSetup::widthPixels)
// Whether a projected patch (areaPixels > 0) is refined: smaller than a pixel, or thin.
inline bool refinedAnalytically(double areaPixels, double widthPixels) {
  return areaPixels < kSubPixelAreaPixels || widthPixels < kThinWidthPixels;
}

struct ProjectedShot {  // what one environment projection left behind
  const std::vector<Patch>& patches;  // the receivers: patches, or elements (solver/meshing/elements.h)
  const Patch& shooter;
  const ProjectionSurface& surface;
  std::span<const ItemBuffer> itemBuffers;        // one per face
  std::span<const double> projectedAreaPixels;    // per patch, over all faces; 0: not projected
  std::span<const double> projectedWidthPixels;   // per patch, the widest face's; 0: not projected
  std::span<const long long> coveredPixels;       // per patch: pixel centres its projection covers
  std::span<const long long> shownPixels;         // per patch: those of them showing it
  const Occluders& occluders;                     // the scene's patches, for those covering no pixel centre
};

// formFactors: per patch, the pixel sums on entry, refined on return.
void refineSubPixelReceivers(const ProjectedShot& shot, ThreadPool& pool,
                             std::vector<double>& formFactors);

}  // namespace radmesh
