#include "solver/formfactors/sub_pixel_receivers.h"

#include <algorithm>
#include <cmath>

#include "solver/formfactors/analytic_form_factor.h"
#include "solver/projection/projection.h"
#include "solver/projection/scan_conversion.h"

namespace radmesh {

namespace {

// The analytic form factor of patch j times the fraction of its covered pixel centres showing
// it. Covering none: hidden where the pixel its centroid falls in shows a surface strictly in front
// of it that the segment from the shooter to j's centroid passes through; seen where it shows
// nothing. Otherwise the pixel cannot say: what it shows may be j's own plane further on (the room
// next door's wall in line with this room's, or one floor under both rooms) beside the wall that
// hides j, or a surface whose plane, not itself, lies in front, so that segment decides, tested
// exactly against every patch.
double visibleFormFactor(const ProjectedShot& shot, int j) {
  const Patch& shooter = shot.shooter;
  const Patch& patch = shot.patches[j];
  const LocalPolygon local = toShooterFrame(shooter, patch);
  const double unhidden = smallPolygonFormFactor(local.corners(), local.centroid, local.normal, patch.areaM2);
  if (shot.coveredPixels[j] > 0)
    return unhidden * static_cast<double>(shot.shownPixels[j]) / static_cast<double>(shot.coveredPixels[j]);
  for (size_t f = 0; f < shot.surface.faces.size(); ++f) {
    const ProjectionFace& face = shot.surface.faces[f];
    const Vec3 c = toFace(face, local.centroid);
    if (!(c.z > 0.0)) continue;
    const glm::dvec2 ab{c.x / c.z, c.y / c.z};
    if (ab.x < face.a0 || ab.x >= face.a1 || ab.y < face.b0 || ab.y >= face.b1) continue;
    const int column = std::min(face.width - 1, static_cast<int>((ab.x - face.a0) / face.pixelWidth()));
    const int row = std::min(face.height - 1, static_cast<int>((ab.y - face.b0) / face.pixelHeight()));
    const int owner = shot.itemBuffers[f].item(column, row);
    if (owner == ItemBuffer::kNone || owner == j) return unhidden;
    const double ownerInverseDepth = inverseDepthAlong(toShooterFrame(shooter, shot.patches[owner]), face, ab);
    const double inverseDepth = 1.0 / c.z;
    // Strictly in front, and where the segment meets it: hidden. In front only by its plane (the top
    // of a shelf, whose plane passes in front of the shelf's thin edge face beyond their common edge)
    // proves nothing, and the exact test decides.
    if (ownerInverseDepth - inverseDepth > kDepthTieTolerance * std::max(std::abs(ownerInverseDepth), inverseDepth) &&
        segmentCrosses(shooter.centroid, patch.centroid, shot.patches[owner]))
      return 0.0;
    return shot.occluders.segmentBlocked(shooter.centroid, patch.centroid, patch.polygon, shooter.polygon) ? 0.0
                                                                                                          : unhidden;
  }
  return 0.0;  // its centroid is outside the projection surface
}

double total(const std::vector<double>& values) {
  double sum = 0.0;
  for (double v : values) sum += v;
  return sum;
}

}  // namespace

void refineSubPixelReceivers(const ProjectedShot& shot, ThreadPool& pool,
                             std::vector<double>& formFactors) {
  std::vector<int> candidates;
  for (size_t j = 0; j < shot.projectedAreaPixels.size(); ++j)
    if (shot.projectedAreaPixels[j] > 0.0 && refinedAnalytically(shot.projectedAreaPixels[j], shot.projectedWidthPixels[j]))
      candidates.push_back(static_cast<int>(j));
  if (candidates.empty()) return;

  const double caught = total(formFactors);
  constexpr int kChunk = 64;
  const int chunks = (static_cast<int>(candidates.size()) + kChunk - 1) / kChunk;
  pool.parallelFor(chunks, [&](int chunk, int) {
    const size_t end = std::min(candidates.size(), static_cast<size_t>(chunk + 1) * kChunk);
    for (size_t c = static_cast<size_t>(chunk) * kChunk; c < end; ++c)
      formFactors[candidates[c]] = visibleFormFactor(shot, candidates[c]);
  });

  // Keep the power the pixels caught; with none caught, keep the analytic values, within what the
  // surface can catch at all.
  const double refined = total(formFactors);
  if (!(refined > 0.0)) return;
  const double target = caught > 0.0 ? caught : std::min(refined, shot.surface.capturedFraction);
  const double scale = target / refined;
  for (double& f : formFactors) f *= scale;
}

}  // namespace radmesh
