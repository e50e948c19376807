#pragma once
// One shot's environment projection (the paper's section 1.5): every patch is projected onto the
// shooter's projection surface, z-buffered into one item buffer per face, and the delta form
// factors of the pixels where each patch is seen are summed (its form factor, before any
// refinement). Rows of pixels are split into fixed bands, so the work spreads over threads while
// the sums stay bitwise the same for any thread count.
#include <memory>
#include <vector>

#include "solver/projection/item_buffer.h"
#include "solver/meshing/patch.h"
#include "solver/projection/projection_surface.h"
#include "solver/projection/scan_conversion.h"
#include "parallel/thread_pool.h"

namespace radmesh {

class EnvironmentProjection {
 public:
  // nearDepth: the near plane, a small length relative to the scene's size. The surface may be
  // shared with other projections (sharedSurface): it is only read.
  EnvironmentProjection(const std::vector<Patch>& patches, std::shared_ptr<const ProjectionSurface> surface,
                        double nearDepth, ThreadPool& pool);
  EnvironmentProjection(const std::vector<Patch>& patches, ProjectionSurface surface, double nearDepth,
                        ThreadPool& pool)
      : EnvironmentProjection(patches, std::make_shared<const ProjectionSurface>(std::move(surface)), nearDepth,
                              pool) {}

  // The list of patches (held by reference) changed, e.g. elements split: what is kept per patch
  // is made again for it, as a new projection would make it.
  void patchesChanged();
  // Frees what is kept from one shot to the next (item buffers, set-ups, bands' lists): a cells
  // solve's cells wait between their turns. The next projection makes them again.
  void releaseScratch();

  void project(int shooter);
  // From a viewpoint that is no patch (a light: its position and frame), every patch but `skip`
  // (-1: none) projected.
  void projectFrom(const Patch& viewpoint, int skip);

  const ProjectionSurface& surface() const { return *surface_; }
  const std::vector<ItemBuffer>& itemBuffers() const { return buffers_; }
  // After project(), per patch: the summed delta form factors of the pixels showing it,
  // its projected area in pixels over all faces, and whether the shooter sees its front.
  const std::vector<double>& pixelFormFactors() const { return pixelFormFactors_; }
  const std::vector<double>& projectedAreaPixels() const { return projectedArea_; }
  // After project(), per patch: the widest of its faces' PolygonSetup::widthPixels (0: not projected).
  const std::vector<double>& projectedWidthPixels() const { return projectedWidth_; }
  const std::vector<char>& seenFromFront() const { return seenFromFront_; }
  // After project(), per patch: the pixel centres its projection covers over all faces, and how
  // many of them show it (fewer: something hides part of it, or a coplanar neighbour won a tie).
  const std::vector<long long>& coveredPixels() const { return coveredPixels_; }
  const std::vector<long long>& shownPixels() const { return shownPixels_; }
  // After project(), per patch: bit f set when its projection reaches face f (a patch's part, an
  // element, reaches no other face).
  const std::vector<unsigned>& facesReached() const { return facesReached_; }

 private:
  struct Band {  // rows [rowBegin, rowEnd) of one face
    int face = 0;
    int rowBegin = 0;
    int rowEnd = 0;
    struct Seen {
      int patch = 0;
      double formFactor = 0.0;  // its pixels' delta form factors
      long long pixels = 0;
    };
    std::vector<const PolygonSetup*> setups;  // polygons reaching these rows, in patch order
    std::vector<long long> covered;           // per setup: the pixel centres it covers in these rows
    std::vector<Seen> sums;                   // per patch seen in the band, in first-seen order
  };

  void makeBuffers();
  void setUpPatches(const Patch& from, int skip);
  void rasteriseBand(Band& band, int worker);

  const std::vector<Patch>& patches_;
  std::shared_ptr<const ProjectionSurface> surface_;
  double nearDepth_;
  ThreadPool& pool_;
  std::vector<int> rank_;
  std::vector<int> shotRank_;  // per patch, this shot's (shotTieRank)
  std::vector<ItemBuffer> buffers_;
  std::vector<Band> bands_;
  std::vector<std::vector<std::vector<PolygonSetup>>> chunkSetups_;  // [chunk][face], patch order
  std::vector<int> firstBandOfFace_;
  std::vector<std::vector<int>> slotOfPatch_;                        // [worker] scratch, -1 when free
  std::vector<double> pixelFormFactors_;
  std::vector<double> projectedArea_;
  std::vector<double> projectedWidth_;
  std::vector<long long> coveredPixels_;
  std::vector<long long> shownPixels_;
  std::vector<char> seenFromFront_;
  std::vector<unsigned> facesReached_;
};

}  // namespace radmesh
