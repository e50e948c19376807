#pragma once
// Receivers smaller than a pixel. A pixel centre either misses such a patch (it gets nothing) or
// hits it (it gets the whole pixel's delta form factor): the aliasing of the paper's section 1.6,
// which for a patch 1e-6 the size of its neighbour makes its radiosity 0 or absurd. Such a patch
// gets instead the analytic point-to-polygon form factor, if the item buffer shows nothing in
// front of its centroid (Baum, Rushmeier & Winget 1989: analytic form factors, visibility from the
// projection). The row is then rescaled to the total the pixels caught, so no power is created or
// lost; the rescale is close to 1 since such patches carry little of it.
#include <span>
#include <vector>

#include "solver/projection/item_buffer.h"
#include "solver/meshing/patch.h"
#include "solver/projection/projection_surface.h"
#include "parallel/thread_pool.h"

namespace radmesh {

inline constexpr double kSubPixelAreaPixels = 1.0;  // projected area below which a patch is refined

struct ProjectedShot {  // what one environment projection left behind
  const std::vector<Patch>& patches;  // the receivers: patches, or elements (solver/meshing/elements.h)
  const Patch& shooter;
  const ProjectionSurface& surface;
  std::span<const ItemBuffer> itemBuffers;        // one per face
  std::span<const int> depthTieRank;              // per patch
  std::span<const double> projectedAreaPixels;    // per patch, over all faces; 0: not projected
};

// formFactors: per patch, the pixel sums on entry, refined on return.
void refineSubPixelReceivers(const ProjectedShot& shot, ThreadPool& pool,
                             std::vector<double>& formFactors);

}  // namespace radmesh
