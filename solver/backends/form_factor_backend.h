#pragma once
// The one interface between progressive refinement and whatever computes form factors: rows
// F_ij for given shooters. The native back end (host CPU) and the mesh back end (the emulated
// SIMD machine) implement it, as pbrt's cpu/ and gpu/ implement one integrator.
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "solver/formfactors/form_factor_row.h"
#include "solver/projection/item_buffer.h"
#include "solver/backends/mesh/mesh_shot_stats.h"
#include "solver/meshing/patch.h"
#include "solver/scene/scene.h"
#include "solver/scene/solve_options.h"

namespace radmesh {

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
  // The emulated machine's running cost counts, on a back end that has one. A shot's costs are
  // differences of them (in floating point, for flops), so a resumed solve restores them to cost
  // its shots bitwise as an uninterrupted one does.
  virtual std::optional<emu::CostCounts> machineCosts() const { return std::nullopt; }
  virtual void restoreMachineCosts(const emu::CostCounts&) {}
};

// The back end options.backend names. Throws OptionError for one that is not available.
std::unique_ptr<FormFactorBackend> makeFormFactorBackend(const Scene& scene,
                                                         const std::vector<Patch>& patches,
                                                         const SolveOptions& options);

}  // namespace radmesh
