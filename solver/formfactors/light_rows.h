#pragma once
// The first (and only) shot of a light without a patch: the scene projected from the light onto
// item buffers, z-buffered by the shared scan conversion, each pixel carrying the fraction of the
// light's power sent through it. A point light sees the six faces of a cube around it, each pixel
// weighted by I dω (dω = dA / r^3 on a face at distance 1); a spot the hemicube around its axis
// (its cone is at most a hemisphere), each pixel by its falloff times dω; a directional light a
// parallel item buffer over its window (solver/scene/scene.h: parallelWindow), each pixel by its
// area. The weights are scaled to sum to 1, so the row and the light's closed-form power balance
// the ledger exactly. Computed on the host for every back end.
#include <vector>

#include "parallel/thread_pool.h"
#include "solver/formfactors/form_factor_row.h"
#include "solver/meshing/patch.h"
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

// Of the scene's lights' power, what never enters the model, as a solve of `patches` at `resolution`
// books it in its first iteration (the sun on a building's walls and roof), W summed over RGB.
double lightsPowerOutside(const Scene& scene, const std::vector<Patch>& patches, int resolution, ThreadPool& pool);

}  // namespace radmesh
