#pragma once
// The first (and only) shot of a light without a patch: the scene projected from the light onto
// item buffers, z-buffered by the shared scan conversion, each pixel carrying the fraction of the
// light's power sent through it. A point light sees the six faces of a cube around it, each pixel
// weighted by I dω (dω = dA / r^3 on a face at distance 1); a spot the hemicube around its axis
// (its cone is at most a hemisphere), each pixel by its falloff times dω; a directional light a
// parallel item buffer over its window (solver/scene/scene.h: parallelWindow), each pixel by its
// area. The weights are scaled to sum to 1, so the row and the light's closed-form power balance
// the ledger exactly. Computed on the host for every back end.
#include <optional>
#include <vector>

#include "parallel/thread_pool.h"
#include "solver/formfactors/form_factor_row.h"
#include "solver/meshing/patch.h"
#include "solver/projection/environment_projection.h"
#include "solver/projection/projection_surface.h"
#include "solver/scene/scene.h"

namespace radmesh {

// The light's projection surface at resolution N per face (N x N for the directional buffer).
ProjectionSurface lightSurface(const Scene& scene, const Light& light, int resolution);

// The viewpoint the light projects from: its position (for a directional light, a point behind
// the scene's patches, centred on its window) and its frame (n along its direction).
Patch lightViewpoint(const Scene& scene, const Light& light, const std::vector<Patch>& patches);

// Where the light's power goes, as fractions of lightPower: receivers seen from the front, the
// backs of one-sided patches, and (1 minus the rest) escaped. shooter is -1.
FormFactorRow lightRow(const Scene& scene, const Light& light, const std::vector<Patch>& patches, int resolution,
                       double nearDepth, ThreadPool& pool);

// lightRow for many lights over the same patches, the same bits: the patches a light sees are listed
// once, and the point lights, whose projection surface is the same wherever they stand, share one
// projection, as a solver's shots share theirs (500 lights each made their own: a surface of 6 x N^2
// weights, item buffers and the patches' tie ranks). Holds the scene, the patches and the pool.
class LightRows {
 public:
  LightRows(const Scene& scene, const std::vector<Patch>& patches, int resolution, double nearDepth, ThreadPool& pool);
  LightRows(const LightRows&) = delete;  // the projection holds the patch list it was made with
  LightRows& operator=(const LightRows&) = delete;
  FormFactorRow row(const Light& light);

 private:
  const Scene& scene_;
  const std::vector<Patch>& patches_;
  int resolution_;
  double nearDepth_;
  ThreadPool& pool_;
  std::vector<int> solid_;            // the patches that are not sky in a window
  std::vector<Patch> solidPatches_;   // those, when some are sky; empty when none is
  std::optional<EnvironmentProjection> points_;  // the point lights', made at the first
};

// Of the scene's lights' power, what never enters the model, as a solve of `patches` at `resolution`
// books it in its first iteration (the sun on a building's walls and roof), W summed over RGB.
double lightsPowerOutside(const Scene& scene, const std::vector<Patch>& patches, int resolution, ThreadPool& pool);

}  // namespace radmesh
