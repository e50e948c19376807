#include "solver/backends/native/native_backend.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "solver/formfactors/analytic_form_factor.h"
#include "solver/formfactors/direction_bins.h"
#include "solver/formfactors/element_shares.h"
#include "solver/projection/hemicube.h"
#include "solver/scene/scene_error.h"
#include "solver/projection/single_plane.h"
#include "solver/formfactors/sub_pixel_receivers.h"

namespace radmesh {

namespace {

constexpr int kAnalyticChunk = 256;
constexpr double kRowSumSlack = 1e-6;  // analytic rows of a convex enclosure sum to 1 within rounding

std::shared_ptr<const ProjectionSurface> singlePlaneFor(const SolveOptions& options) {
  return sharedSurface(fmt::format("plane {} {:a}", options.resolution, options.ratio),
                       [&] { return makeSinglePlane(options.resolution, options.ratio); });
}

std::shared_ptr<const ProjectionSurface> surfaceFor(const SolveOptions& options) {
  switch (options.projection) {
    case Projection::Plane: return singlePlaneFor(options);
    case Projection::Hemicube:
      return sharedSurface(fmt::format("hemicube {}", options.resolution),
                           [&] { return makeHemicube(options.resolution); });
    case Projection::Analytic: break;
  }
  return nullptr;
}

}  // namespace

NativeBackend::NativeBackend(const Scene& scene, const std::vector<Patch>& patches,
                             const SolveOptions& options)
    : NativeBackend(scene, patches, patches, nullptr, options) {}

NativeBackend::NativeBackend(const Scene& scene, const std::vector<Patch>& patches, const Elements& elements,
                             const SolveOptions& options)
    : NativeBackend(scene, patches, elements.elements, &elements, options) {}

NativeBackend::NativeBackend(const Scene& scene, const std::vector<Patch>& patches,
                             const std::vector<Patch>& receivers, const Elements* elements,
                             const SolveOptions& options)
    : scene_(scene),
      patches_(patches),
      receivers_(receivers),
      elements_(elements),
      shares_(elements && resolvedElementRows(options) == ElementRows::Share),
      options_(options),
      nearDepth_(sceneNearDepth(patches)),
      pool_(options.threads) {
  validateOptions(options);
  takeReceivers();
}

void NativeBackend::takeReceivers() {
  formFactors_.assign(receivers_.size(), 0.0);
  seenFromFront_.assign(receivers_.size(), 0);
  if (!projection_) {
    if (auto surface = surfaceFor(options_))
      projection_ = std::make_unique<EnvironmentProjection>(shares_ ? patches_ : receivers_, std::move(surface),
                                                            nearDepth_, pool_);
    return;
  }
  // Split elements: the projections keep their surfaces and pixel tables, and re-read the receivers.
  if (!shares_) projection_->patchesChanged();
  if (singlePlane_) singlePlane_->patchesChanged();
}

void NativeBackend::receiversSplit(std::span<const int>) { takeReceivers(); }

void NativeBackend::releaseScratch() {
  for (EnvironmentProjection* projection : {projection_.get(), singlePlane_.get()})
    if (projection) projection->releaseScratch();
}

NativeBackend::~NativeBackend() = default;

ProjectionSummary NativeBackend::projectionSummary() const {
  if (!projection_) return {};  // analytic: the whole hemisphere, exactly
  return {projection_->surface().capturedFraction, projection_->surface().tableSum};
}

void NativeBackend::binDirections(std::span<const int> shooters, int n) {
  directional_.assign(patches_.size(), 0);
  for (int j : shooters) directional_.at(static_cast<size_t>(j)) = 1;
  binsN_ = n;
  binTotals_.assign(directionBinCount(n), 0.0);
  pixelBin_.clear();
  if (!projection_) {
    for (size_t b = 0; b < binTotals_.size(); ++b) binTotals_[b] = directionBinFormFactor(n, static_cast<int>(b));
    return;
  }
  const ProjectionSurface& surface = projection_->surface();
  for (size_t f = 0; f < surface.faces.size(); ++f) {
    const ProjectionFace& face = surface.faces[f];
    std::vector<int>& bins = pixelBin_.emplace_back(surface.deltaFormFactors[f].size());
    for (int row = 0; row < face.height; ++row)
      for (int column = 0; column < face.width; ++column) {
        const size_t q = static_cast<size_t>(row) * face.width + column;
        bins[q] = directionBin(n, face.toLocal(face.pixelCentre(column, row)));
        binTotals_[bins[q]] += surface.deltaFormFactors[f][q];
      }
  }
}

void NativeBackend::computeRows(std::span<const int> shooters, std::vector<FormFactorRow>& rows) {
  rows.resize(shooters.size());
  for (size_t s = 0; s < shooters.size(); ++s)
    rows[s] = projection_ ? projectedRow(*projection_, shooters[s]) : analyticRow(shooters[s]);
}

ItemBuffer NativeBackend::singlePlaneItemBuffer(int shooter) {
  const bool same = options_.projection == Projection::Plane && !shares_;
  if (!same && !singlePlane_)
    singlePlane_ = std::make_unique<EnvironmentProjection>(
        receivers_, singlePlaneFor(options_), nearDepth_, pool_);
  EnvironmentProjection& plane = same ? *projection_ : *singlePlane_;
  plane.projectFrom(patches_[shooter], skipOf(shooter));
  return plane.itemBuffers()[0];
}

FormFactorRow NativeBackend::projectedRow(EnvironmentProjection& projection, int shooter) {
  if (shares_) {
    shareShot(projection, shooter);
    FormFactorRow row = assembleRow(shooter, projection.surface().capturedFraction, formFactors_, seenFromFront_);
    if (!directional_.empty() && directional_[shooter]) addPixelBins(projection, row);
    return row;
  }
  projection.projectFrom(patches_[shooter], skipOf(shooter));
  formFactors_ = projection.pixelFormFactors();
  seenFromFront_ = projection.seenFromFront();
  if (refinesRow(shooter)) refineSubPixelReceivers(shotOf(projection, shooter, receivers_), pool_, formFactors_);
  FormFactorRow row = assembleRow(shooter, projection.surface().capturedFraction, formFactors_, seenFromFront_);
  if (!directional_.empty() && directional_[shooter]) addPixelBins(projection, row);
  return row;
}

ProjectedShot NativeBackend::shotOf(const EnvironmentProjection& projection, int shooter,
                                    const std::vector<Patch>& receivers) {
  if (!occluders_) occluders_.emplace(patches_);
  return {receivers, patches_[shooter], projection.surface(), projection.itemBuffers(),
          projection.projectedAreaPixels(), projection.projectedWidthPixels(), projection.coveredPixels(),
          projection.shownPixels(), *occluders_};
}

bool NativeBackend::refinesRow(int shooter) const {
  return options_.subPixelReceivers && (directional_.empty() || !directional_[shooter]);
}

// The patches projected, their pixel sums refined below a pixel as patches' rows are, and shared
// among their elements.
void NativeBackend::shareShot(EnvironmentProjection& projection, int shooter) {
  projection.projectFrom(patches_[shooter], shooter);
  patchFormFactors_ = projection.pixelFormFactors();
  patchSeenFromFront_ = projection.seenFromFront();
  const ProjectedShot shot = shotOf(projection, shooter, patches_);
  if (refinesRow(shooter)) refineSubPixelReceivers(shot, pool_, patchFormFactors_);
  const PatchShot patchShot{patchFormFactors_, patchSeenFromFront_, projection.coveredPixels(),
                            projection.shownPixels(), projection.facesReached()};
  shareAmongElements(shot, nearDepth_, patchShot, *elements_, pool_, formFactors_, seenFromFront_);
}

// Each pixel's delta form factor summed per patch and bin, in pixel order whatever the threads.
// Sharing rows, each element takes of its patch's bins its share of the patch's form factor.
void NativeBackend::addPixelBins(const EnvironmentProjection& projection, FormFactorRow& row) const {
  if (!shares_) return addPatchPixelBins(projection, seenFromFront_, row);
  FormFactorRow patchRow;
  addPatchPixelBins(projection, patchSeenFromFront_, patchRow);
  row.binTotals = std::move(patchRow.binTotals);
  row.binBackFaces = std::move(patchRow.binBackFaces);
  for (size_t k = 0; k < patchRow.binShares.size();) {  // a patch's shares are consecutive, by bin
    const int p = patchRow.binShares[k].patch;
    size_t end = k;
    while (end < patchRow.binShares.size() && patchRow.binShares[end].patch == p) ++end;
    for (int e = elements_->first[p]; e < elements_->first[p + 1]; ++e)
      if (formFactors_[e] > 0.0)
        for (size_t b = k; b < end; ++b)
          row.binShares.push_back({e, patchRow.binShares[b].bin,
                                   patchRow.binShares[b].formFactor * (formFactors_[e] / patchFormFactors_[p])});
    k = end;
  }
}

void NativeBackend::addPatchPixelBins(const EnvironmentProjection& projection, const std::vector<char>& seenFromFront,
                                      FormFactorRow& row) const {
  const long long bins = static_cast<long long>(binTotals_.size());
  std::vector<std::pair<long long, double>> hits;  // (patch * bins + bin, delta form factor)
  for (size_t f = 0; f < projection.itemBuffers().size(); ++f) {
    const std::vector<int>& items = projection.itemBuffers()[f].items;
    for (size_t q = 0; q < items.size(); ++q)
      if (items[q] != ItemBuffer::kNone)
        hits.emplace_back(items[q] * bins + pixelBin_[f][q], projection.surface().deltaFormFactors[f][q]);
  }
  std::stable_sort(hits.begin(), hits.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  row.binTotals = binTotals_;
  row.binBackFaces.assign(binTotals_.size(), 0.0);
  for (size_t k = 0; k < hits.size();) {
    const long long key = hits[k].first;
    double sum = 0.0;
    for (; k < hits.size() && hits[k].first == key; ++k) sum += hits[k].second;
    const int patch = static_cast<int>(key / bins), bin = static_cast<int>(key % bins);
    if (seenFromFront[patch])
      row.binShares.push_back({patch, bin, sum});
    else
      row.binBackFaces[bin] += sum;
  }
}

void NativeBackend::addAnalyticBins(int shooter, FormFactorRow& row) const {
  row.binTotals = binTotals_;
  row.binBackFaces.assign(binTotals_.size(), 0.0);
  for (size_t j = 0; j < receivers_.size(); ++j) {
    if (!(formFactors_[j] > 0.0)) continue;
    const LocalPolygon local = toShooterFrame(patches_[shooter], receivers_[j]);
    splitOverDirectionBins(binsN_, local.corners(), [&](int bin, double f) {
      if (!(f > 0.0)) return;
      if (seenFromFront_[j])
        row.binShares.push_back({static_cast<int>(j), bin, f});
      else
        row.binBackFaces[bin] += f;
    });
  }
}

FormFactorRow NativeBackend::analyticRow(int shooter) {
  const Patch& from = patches_[shooter];
  const int n = static_cast<int>(receivers_.size());
  const int skip = skipOf(shooter);
  pool_.parallelFor((n + kAnalyticChunk - 1) / kAnalyticChunk, [&](int chunk, int) {
    for (int j = chunk * kAnalyticChunk; j < std::min(n, (chunk + 1) * kAnalyticChunk); ++j) {
      formFactors_[j] = 0.0;
      seenFromFront_[j] = 0;
      if (j == skip) continue;
      const LocalPolygon local = toShooterFrame(from, receivers_[j]);
      if (std::abs(local.planeOffset) <= nearDepth_) continue;  // coplanar or edge-on
      seenFromFront_[j] = local.seenFromFront();
      formFactors_[j] = pointToPolygonFormFactor(local.corners());
    }
  });
  FormFactorRow row = assembleRow(shooter, 1.0, formFactors_, seenFromFront_);
  const double sum = row.hitFraction();
  if (sum > 1.0 + kRowSumSlack) {
    const Patch& p = patches_[shooter];
    const bool known = p.polygon >= 0 && p.polygon < static_cast<int>(scene_.polygons.size());
    const std::string origin = known && !scene_.polygons[p.polygon].origin.empty()
                                   ? " (" + scene_.polygons[p.polygon].origin + ")"
                                   : "";
    throw SceneError(scene_.source, fmt::format("patch {} of polygon {}{}", shooter, p.polygon, origin),
                     fmt::format("its analytic form factors sum to {:.6f} > 1: patches hide one "
                                 "another, so the scene is not a convex enclosure and form factors "
                                 "without occlusion would create light",
                                 sum),
                     "use --projection hemicube (or plane), which resolve occlusion");
  }
  if (sum > 1.0) {  // rounding, within the slack: not light to create
    for (double& f : row.formFactors) f /= sum;
    row.backFaces /= sum;
  }
  if (!directional_.empty() && directional_[shooter]) addAnalyticBins(shooter, row);
  return row;
}

}  // namespace radmesh
