#include "solver/projection/environment_projection.h"

#include <algorithm>
#include <optional>

namespace radmesh {

namespace {

constexpr int kBandRows = 16;            // rows of pixels per task
constexpr int kSetupChunkPatches = 256;  // patches per set-up task

}  // namespace

EnvironmentProjection::EnvironmentProjection(const std::vector<Patch>& patches,
                                             std::shared_ptr<const ProjectionSurface> surface, double nearDepth,
                                             ThreadPool& pool)
    : patches_(patches),
      surface_(std::move(surface)),
      nearDepth_(nearDepth),
      pool_(pool) {
  makeBuffers();
  const int faces = static_cast<int>(surface_->faces.size());
  for (int f = 0; f < faces; ++f) {
    const ProjectionFace& face = surface_->faces[f];
    firstBandOfFace_.push_back(static_cast<int>(bands_.size()));
    for (int row = 0; row < face.height; row += kBandRows)
      bands_.push_back({f, row, std::min(row + kBandRows, face.height), {}, {}, {}});
  }
  patchesChanged();
}

void EnvironmentProjection::patchesChanged() {
  const size_t n = patches_.size();
  rank_ = depthTieRanks(patches_);
  slotOfPatch_.assign(pool_.size(), std::vector<int>(n, -1));
  pixelFormFactors_.assign(n, 0.0);
  projectedArea_.assign(n, 0.0);
  projectedWidth_.assign(n, 0.0);
  coveredPixels_.assign(n, 0);
  shownPixels_.assign(n, 0);
  seenFromFront_.assign(n, 0);
  shotRank_.assign(n, 0);
  facesReached_.assign(n, 0);
  for (Band& band : bands_) band.setups.clear();  // they point into chunkSetups_
  chunkSetups_.assign((n + kSetupChunkPatches - 1) / kSetupChunkPatches,
                      std::vector<std::vector<PolygonSetup>>(surface_->faces.size()));
}

void EnvironmentProjection::makeBuffers() {
  for (const ProjectionFace& face : surface_->faces) buffers_.emplace_back(face.width, face.height);
}

void EnvironmentProjection::releaseScratch() {
  buffers_ = {};
  for (Band& band : bands_) band.setups = {}, band.covered = {}, band.sums = {};
  for (auto& chunk : chunkSetups_)
    for (std::vector<PolygonSetup>& faceSetups : chunk) faceSetups = {};
}

void EnvironmentProjection::setUpPatches(const Patch& from, int skip) {
  const bool parallel = surface_->faces.front().parallel;
  const int n = static_cast<int>(patches_.size());
  pool_.parallelFor(static_cast<int>(chunkSetups_.size()), [&](int chunk, int) {
    auto& out = chunkSetups_[chunk];
    for (auto& faceSetups : out) faceSetups.clear();
    ScreenPolygon screen;
    const int end = std::min(n, (chunk + 1) * kSetupChunkPatches);
    for (int j = chunk * kSetupChunkPatches; j < end; ++j) {
      projectedArea_[j] = 0.0;
      projectedWidth_[j] = 0.0;
      seenFromFront_[j] = 0;
      facesReached_[j] = 0;
      if (j == skip) continue;
      const std::optional<LocalPolygon> local = inSurfaceView(*surface_, from, patches_[j]);
      if (!local) continue;
      // A parallel beam meets a front that faces against it, wherever the patch lies.
      seenFromFront_[j] = parallel ? local->normal.z < 0.0 : local->seenFromFront();
      shotRank_[j] = shotTieRank(rank_[j], seenFromFront_[j], n);
      for (size_t f = 0; f < out.size(); ++f) {
        // setUpProjection's two steps apart: most faces refuse the patch in the first, and a set-up
        // (a few hundred bytes, cleared when made, so made in place) is made only for the rest.
        const ProjectionFace& face = surface_->faces[f];
        if (!projectOntoFace(*local, face, nearDepth_, screen)) continue;
        PolygonSetup& setup = out[f].emplace_back();
        if (setupPolygon(screen, face.width, face.height, j, shotRank_[j], setup)) {
          projectedArea_[j] += setup.areaPixels;
          projectedWidth_[j] = std::max(projectedWidth_[j], setup.widthPixels);
          facesReached_[j] |= 1u << f;
        } else
          out[f].pop_back();
      }
    }
  });

  // Hand each band the polygons that reach its rows, in patch order.
  for (Band& band : bands_) band.setups.clear();
  for (const auto& chunk : chunkSetups_)
    for (size_t f = 0; f < chunk.size(); ++f)
      for (const PolygonSetup& setup : chunk[f])
        for (int row = setup.rowBegin / kBandRows * kBandRows; row < setup.rowEnd; row += kBandRows)
          bands_[firstBandOfFace_[f] + row / kBandRows].setups.push_back(&setup);
}

void EnvironmentProjection::rasteriseBand(Band& band, int worker) {
  ItemBuffer& buffer = buffers_[band.face];
  buffer.clearRows(band.rowBegin, band.rowEnd);
  band.covered.clear();
  for (const PolygonSetup* setup : band.setups)
    band.covered.push_back(rasterise(*setup, buffer, band.rowBegin, band.rowEnd, shotRank_));

  // Form-factor phase: the delta form factor of every pixel goes to the patch seen there.
  std::vector<int>& slot = slotOfPatch_[worker];
  const std::vector<double>& df = surface_->deltaFormFactors[band.face];
  band.sums.clear();
  const size_t begin = static_cast<size_t>(band.rowBegin) * buffer.width;
  const size_t end = static_cast<size_t>(band.rowEnd) * buffer.width;
  // A patch covers runs of pixels: each run is summed in registers, in pixel order as before (the
  // same bits), and looked up once.
  for (size_t q = begin; q < end;) {
    const int id = buffer.items[q];
    if (id == ItemBuffer::kNone) {
      ++q;
      continue;
    }
    if (slot[id] < 0) {
      slot[id] = static_cast<int>(band.sums.size());
      band.sums.push_back({id, df[q++], 1});
    }
    Band::Seen& seen = band.sums[slot[id]];
    double formFactor = seen.formFactor;
    const size_t first = q;
    for (; q < end && buffer.items[q] == id; ++q) formFactor += df[q];
    seen.formFactor = formFactor;
    seen.pixels += static_cast<long long>(q - first);
  }
  for (const Band::Seen& seen : band.sums) slot[seen.patch] = -1;
}

void EnvironmentProjection::project(int shooter) { projectFrom(patches_[shooter], shooter); }

void EnvironmentProjection::projectFrom(const Patch& viewpoint, int skip) {
  if (buffers_.empty()) makeBuffers();  // released since the last shot
  setUpPatches(viewpoint, skip);
  pool_.parallelFor(static_cast<int>(bands_.size()),
                    [&](int b, int worker) { rasteriseBand(bands_[b], worker); });
  // Bands are summed in a fixed order: the same bits whatever thread did which band.
  std::fill(pixelFormFactors_.begin(), pixelFormFactors_.end(), 0.0);
  std::fill(coveredPixels_.begin(), coveredPixels_.end(), 0);
  std::fill(shownPixels_.begin(), shownPixels_.end(), 0);
  for (const Band& band : bands_) {
    for (const Band::Seen& seen : band.sums) {
      pixelFormFactors_[seen.patch] += seen.formFactor;
      shownPixels_[seen.patch] += seen.pixels;
    }
    for (size_t k = 0; k < band.setups.size(); ++k) coveredPixels_[band.setups[k]->id] += band.covered[k];
  }
}

}  // namespace radmesh
