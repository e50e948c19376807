#include "solver/formfactors/element_shares.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "solver/formfactors/analytic_form_factor.h"
#include "solver/projection/scan_conversion.h"

namespace radmesh {

namespace {

constexpr int kShareChunkPatches = 64;

// Where an element lands on the projection surface: the pixel centres it covers, how many of them
// show its patch `item`, and whether it reaches any face's window at all.
struct Cover {
  long long covered = 0;
  long long showing = 0;
  bool onSurface = false;
};

// Only the faces its patch reaches (`faces`, a bit each) can hold it.
Cover coverOf(const ProjectedShot& shot, const LocalPolygon& local, double nearDepth, int item, unsigned faces) {
  Cover c;
  PolygonSetup setup;
  for (size_t f = 0; f < shot.surface.faces.size(); ++f) {
    if (!(faces >> f & 1u) || !setUpProjection(local, shot.surface.faces[f], nearDepth, item, 0, setup)) continue;
    c.onSurface = true;
    const ItemBuffer& buffer = shot.itemBuffers[f];
    for (int row = setup.rowBegin; row < setup.rowEnd; ++row) {
      const auto [left, right] = rowSpan(setup, row);
      const int* items = buffer.items.data() + static_cast<std::ptrdiff_t>(row) * buffer.width;
      c.covered += right - left;
      for (int column = left; column < right; ++column) c.showing += items[column] == item;
    }
  }
  return c;
}

// Whether a window that does not hold the whole hemisphere (the single plane) cuts the patch: then
// its elements outside the window get nothing, as their pixels do.
bool cutByWindow(const ProjectedShot& shot, double nearDepth, int p) {
  if (!(shot.surface.capturedFraction < 1.0)) return false;
  const std::optional<LocalPolygon> local = inSurfaceView(shot.surface, shot.shooter, shot.patches[p]);
  PolygonSetup setup;
  for (const ProjectionFace& face : shot.surface.faces)
    if (local && setUpProjection(*local, face, nearDepth, p, 0, setup) &&
        (setup.columnBegin == 0 || setup.rowBegin == 0 || setup.columnEnd == face.width || setup.rowEnd == face.height))
      return true;
  return false;
}

// Whether every element of a patch (in the shooter's frame) passes smallPolygonFormFactor's test
// because the patch does with room to spare: an element lies inside its patch, so it is in front
// where the patch is, no wider, and no nearer than the patch's centroid less the patch's diameter.
bool elementsSmallAndFar(const LocalPolygon& patch) {
  const std::span<const Vec3> corners = patch.corners();
  if (!std::all_of(corners.begin(), corners.end(), [](const Vec3& v) { return v.z > 0.0; })) return false;
  const double diameter = std::sqrt(squaredDiameter(corners));
  return diameter <= kSmallPolygonRatio * (glm::length(patch.centroid) - diameter);
}

// Patch p's form factor f shared among its elements: by their closed forms where the item buffer
// shows the patch whole, each times the fraction of its pixels that show the patch where not.
void sharePatch(const ProjectedShot& shot, double nearDepth, const PatchShot& patches, int p,
                const Elements& elements, std::vector<double>& weight, std::vector<double>& out) {
  const int begin = elements.first[p], end = elements.first[p + 1];
  const long long covered = patches.coveredPixels[p], shown = patches.shownPixels[p];
  const bool partly = shown < covered || cutByWindow(shot, nearDepth, p);
  const double patchShown = covered > 0 ? static_cast<double>(shown) / static_cast<double>(covered) : 1.0;
  weight.assign(static_cast<size_t>(end - begin), 0.0);
  double sum = 0.0;
  // A small far patch (elementsSmallAndFar): each element's closed form is the differential one,
  // from its centroid and normal alone.
  if (!partly && elementsSmallAndFar(toShooterFrame(shot.shooter, shot.patches[p]))) {
    for (int e = begin; e < end; ++e) {
      const Patch& element = elements.elements[e];
      weight[e - begin] = differentialFormFactor(toShooterFrame(shot.shooter, element.centroid),
                                                 directionInShooterFrame(shot.shooter, element.normal), element.areaM2);
      sum += weight[e - begin];
    }
  } else {
    for (int e = begin; e < end; ++e) {
      const std::optional<LocalPolygon> local = inSurfaceView(shot.surface, shot.shooter, elements.elements[e]);
      if (!local) continue;
      double w = smallPolygonFormFactor(local->corners(), local->centroid, local->normal, elements.elements[e].areaM2);
      if (partly && w > 0.0) {
        const Cover c = coverOf(shot, *local, nearDepth, p, patches.facesReached[p]);
        // An element between pixel centres takes its patch's shown fraction.
        w *= !c.onSurface ? 0.0 : c.covered > 0 ? static_cast<double>(c.showing) / static_cast<double>(c.covered)
                                                : patchShown;
      }
      weight[e - begin] = w;
      sum += w;
    }
  }
  const double f = patches.formFactors[p];
  for (int e = begin; e < end; ++e)
    out[e] = sum > 0.0 ? f * (weight[e - begin] / sum) : f / (end - begin);  // no closed form: evenly
}

}  // namespace

void shareAmongElements(const ProjectedShot& shot, double nearDepth, const PatchShot& patches, const Elements& elements,
                        ThreadPool& pool, std::vector<double>& elementFormFactors,
                        std::vector<char>& elementSeenFromFront) {
  const int count = static_cast<int>(elements.first.size()) - 1;
  elementFormFactors.assign(elements.elements.size(), 0.0);
  elementSeenFromFront.assign(elements.elements.size(), 0);
  pool.parallelFor((count + kShareChunkPatches - 1) / kShareChunkPatches, [&](int chunk, int) {
    std::vector<double> weight;
    for (int p = chunk * kShareChunkPatches; p < std::min(count, (chunk + 1) * kShareChunkPatches); ++p) {
      const int begin = elements.first[p], end = elements.first[p + 1];
      const char front = patches.seenFromFront[p];
      std::fill(elementSeenFromFront.begin() + begin, elementSeenFromFront.begin() + end, front);
      if (!(patches.formFactors[p] > 0.0)) continue;
      if (end - begin == 1 || !front)
        elementFormFactors[begin] = patches.formFactors[p];  // a back face's light only counts in sum
      else
        sharePatch(shot, nearDepth, patches, p, elements, weight, elementFormFactors);
    }
  });
}

}  // namespace radmesh
