#pragma once
// Progressive refinement by shooting (the paper's sections 1.2 and 1.5): step() shoots the k
// patches with the most unshot power. The CLI loops step(); the viewer interleaves it with frames.
// It plans the effects the scene calls for (options.effects) and skips the rest, exactly.
#include <memory>
#include <vector>

#include "solver/radiosity/effects_plan.h"
#include "solver/backends/form_factor_backend.h"
#include "solver/meshing/patch.h"
#include "solver/scene/scene.h"
#include "solver/scene/solve_options.h"

namespace radmesh {

// Where the emitted power went, in watts summed over RGB. Balances:
// emitted = absorbed + unshot + notCaptured + escaped.
struct Ledger {
  double emitted = 0.0;
  double absorbed = 0.0;     // absorbed by patches: (1 - rho) of what reached them
  double unshot = 0.0;       // reflected but not yet shot on: sum of dB_j * A_j
  double notCaptured = 0.0;  // left the shooter outside the projection surface (the plane's miss)
  double escaped = 0.0;      // captured but hit no patch: light leaving an open scene
  double absorbedByBackFaces = 0.0;  // part of absorbed: reached the unlit back of a one-sided patch
  double imbalance() const;  // |emitted - (absorbed + unshot + notCaptured + escaped)| / emitted
  double unshotFraction() const;  // unshot / emitted: what is left to distribute (0 if nothing emits)
};

struct IterationRecord {
  int iteration = 0;               // 1-based
  std::vector<int> shooters;       // patch indices shot this iteration
  double shotPowerW = 0.0;         // summed over the shooters and RGB
  double convergence = 0.0;        // C_i = 1 - s_i / s_1
  double seconds = 0.0;            // wall time of this iteration
  double capturedFraction = 0.0;   // sum of delta form factors of the projection surface
  int reusedRows = 0;       // shooters this iteration that had shot before (the paper's Table 1.3)
  int reusedRowsTotal = 0;  // the same, over all iterations so far
  int cacheHits = 0;        // rows served by the form-factor cache this iteration
  Ledger ledger;            // after this iteration
  // Mesh backend only: depths at stages (a) and (b) (histograms; per-PE lists dropped) and the
  // emulated cost of this iteration: shooter selection, the shot and the radiosity update. Null
  // on the native backend; no depths (empty histograms) on a cache hit, where nothing is projected.
  std::shared_ptr<const MeshShotStats> meshShot;
};

// Throws SceneError for input it cannot solve (NaN or infinite coordinates or emittance, an area
// that is not positive, rho outside [0, 1], an unknown material), naming the element and value;
// step() throws SolveError when the energy ledger stops balancing, naming the iteration and terms.
class ProgressiveSolver {
 public:
  ProgressiveSolver(const Scene& scene, std::vector<Patch> patches, const SolveOptions& options);
  // With the given back end instead of the one options.backend names (tests inject faults).
  ProgressiveSolver(const Scene& scene, std::vector<Patch> patches, const SolveOptions& options,
                    std::unique_ptr<FormFactorBackend> backend);
  ~ProgressiveSolver();
  ProgressiveSolver(const ProgressiveSolver&) = delete;
  ProgressiveSolver& operator=(const ProgressiveSolver&) = delete;

  const IterationRecord& step();  // one iteration: shoot k patches
  bool done() const;              // convergence >= until, max iterations, or nothing left to shoot
  double convergence() const;

  const std::vector<Patch>& patches() const;
  const std::vector<Rgb>& radiosity() const;  // B per patch, W/m^2
  std::vector<Rgb> displayRadiosity() const;  // B plus the display-only ambient term
  const Ledger& ledger() const;
  const std::vector<IterationRecord>& history() const;
  // The options in force: as given, but with an analytic projection where occlusion is off.
  const SolveOptions& options() const;
  const EffectsPlan& effectsPlan() const;  // what is simulated and why

  // What the projection surface catches (closed form and sum of delta form factors).
  ProjectionSummary projectionSummary() const;
  // The back end computing form factors (e.g. for its single plane's item buffer).
  FormFactorBackend& backend();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace radmesh
