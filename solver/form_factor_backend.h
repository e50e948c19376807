#pragma once
// The one interface between progressive refinement and whatever computes form factors: rows
// F_ij for given shooters. The native back end (host CPU) and the mesh back end (the emulated
// SIMD machine) implement it, as pbrt's cpu/ and gpu/ implement one integrator.
#include <memory>
#include <span>
#include <vector>

#include "solver/item_buffer.h"
#include "solver/mesh_shot_stats.h"
#include "solver/patch.h"
#include "solver/scene.h"
#include "solver/solve_options.h"

namespace radmesh {

// Where a shooter's power goes, as fractions of it.
struct FormFactorRow {
  int shooter = -1;
  std::vector<int> receivers;       // patches whose front the shooter sees, ascending
  std::vector<double> formFactors;  // F_ij for each receiver, > 0
  double backFaces = 0.0;           // reaches the unlit back of one-sided patches (absorbed there)
  double capturedFraction = 1.0;    // caught by the projection surface (the rest: not captured)
  bool reused = false;              // served from the form-factor cache, not computed

  double hitFraction() const;       // sum of formFactors, plus backFaces
  // Caught but hitting no patch: light leaving an open scene. Never negative.
  double escapedFraction() const;
  std::size_t bytes() const;        // memory the row holds
};

// What the projection surface catches: the closed form, and the sum of its delta form factors.
struct ProjectionSummary {
  double capturedFraction = 1.0;
  double deltaFormFactorSum = 1.0;
};

class FormFactorBackend {
 public:
  virtual ~FormFactorBackend() = default;
  // One row per shooter, all from the same scene; rows is resized to shooters.size().
  virtual void computeRows(std::span<const int> shooters, std::vector<FormFactorRow>& rows) = 0;
  virtual ProjectionSummary projectionSummary() const = 0;
  // The single plane's item buffer for a shooter, at the options' resolution and ratio, whatever
  // the projection in use: what the viewer shows, and where the back ends must agree pixel for pixel.
  virtual ItemBuffer singlePlaneItemBuffer(int shooter) = 0;
  // Load balance and emulated cost of the last computeRows, on a back end that has them.
  virtual const MeshShotStats* lastMeshShot() const { return nullptr; }
};

// The back end options.backend names. Throws OptionError for one that is not available.
std::unique_ptr<FormFactorBackend> makeFormFactorBackend(const Scene& scene,
                                                         const std::vector<Patch>& patches,
                                                         const SolveOptions& options);

}  // namespace radmesh
