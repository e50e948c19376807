#pragma once
// Progressive refinement by shooting (the paper's sections 1.2 and 1.5): step() shoots the k
// patches with the most unshot power. The CLI loops step(); the viewer interleaves it with frames.
// It plans the effects the scene calls for (options.effects) and skips the rest, exactly.
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "solver/radiosity/effects_plan.h"
#include "solver/radiosity/ledger.h"
#include "solver/backends/form_factor_backend.h"
#include "solver/meshing/patch.h"
#include "solver/scene/scene.h"
#include "solver/scene/solve_options.h"

namespace radmesh {

// A solve that stops with more than this fraction of the emitted power unshot is far from
// converged (docs/accuracy.md: its reflected light is tens of per cent wrong); the CLI and the
// viewer's panel say so.
constexpr double kFarFromConvergedUnshot = 0.10;

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
  int elementsSplit = 0;    // --subdivide adaptive: elements split after this iteration's shots
  // What this iteration did on the back end's machine (the mesh back end: the emulated cost of
  // shooter selection, the shot and the radiosity update, and the item-buffer depths, none on a
  // cache hit, where nothing is projected). Null on a back end without figures.
  std::shared_ptr<const ShotStats> shotStats;
};

// What a solve has accumulated beyond its scene and options: with them, all it takes to go on
// bitwise as if it had never stopped (solver/radiosity/checkpoint.h saves it).
struct SolverProgress {
  std::vector<Rgb> radiosity;
  std::vector<Rgb> unshotRadiosity;
  std::vector<double> unshotPowerW;
  std::vector<int> timesShot;  // per patch: for the reuse counts
  Ledger ledger;
  std::vector<IterationRecord> history;
  double firstShotPowerW = 0.0;  // s_1 of C_i = 1 - s_i / s_1
  double convergence = 0.0;
  bool exhausted = false;
  std::string machineState;  // the back end's (FormFactorBackend::machineState)
  // The form-factor cache, most recently used first. On the mesh back end a row computed with
  // other shooters beside it differs in its last bits, so which rows the cache serves matters.
  std::vector<FormFactorRow> cachedRows;
  std::vector<Rgb> elementRadiosity;  // per element when patches are cut into elements; else empty
  // --subdivide adaptive: per element, its level (its patch's split tree, splitToLevels in
  // solver/meshing/elements.h), and per patch all it has shot (for --split-regather all); else empty.
  std::vector<int> elementLevels;
  std::vector<Rgb> shotTotal;
  // Portal patches (setPortalPatches): per patch, the power waiting on it and its unshot power per
  // direction bin; empty for other patches.
  std::vector<std::vector<Rgb>> portalPower;
  std::vector<std::vector<Rgb>> portalUnshot;
};

// Throws SceneError for input it cannot solve (NaN or infinite coordinates or emittance, an area
// that is not positive, rho outside [0, 1], an unknown material, a light validateScene refuses),
// naming the element and value;
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

  // One iteration: shoot k patches. It steps past the stopping rule (done()) when asked; once
  // nothing is left to shoot (exhausted()), it returns the last record.
  const IterationRecord& step();
  // Convergence >= until, unshot at most untilUnshot (or kLedgerTolerance) of the emitted with
  // every emitting patch shot (when untilUnshot > 0; those left shoot first once the rest is
  // under it), max iterations, or nothing left to shoot.
  bool done() const;
  bool exhausted() const;         // no patch has unshot power: the solution is exact
  int emittersToShoot() const;    // emitting patches with power that have not shot yet
  // Portal patches (a cell of a cells solve): light reaching their front is neither reflected nor
  // absorbed but waits on them (ledger portalOut) until takePortalPower() moves it to the
  // neighbour cell, whose solve receives it with addPortalPower() (ledger portalIn) as unshot
  // power of its twin patch. Call before the first step. With binsN > 1 the power is kept per bin
  // of its direction of travel (directionBinCount(binsN) bins, solver/formfactors/direction_bins.h,
  // in the frame of the patch's back: the twin's), and a portal patch shoots each bin's power into
  // that bin's directions; binsN <= 1: one bin, shot diffusely. Throws OptionError when the back
  // end cannot split rows by direction, or when patches are cut into elements (not built yet).
  void setPortalPatches(const std::vector<int>& portalPatches, int binsN = 0);
  Rgb portalPower(int patch) const;  // what waits on the portal patch, all bins
  std::vector<Rgb> takePortalPower(int patch);  // per bin, leaving it empty
  // Per bin, as many as the patch has (std::invalid_argument otherwise, or for no portal patch).
  void addPortalPower(int patch, std::span<const Rgb> bins);
  // A cells solve's share of a light's one shot over the whole building (CellSolver): `row` gives
  // the fraction of the light's `power` reaching each of this solve's patches (local indices,
  // ascending). It arrives as emitted power (ledger emitted), absorbed and reflected as in the
  // whole solve's first iteration. Returns the watts booked. Call before the first step.
  double receiveLight(FormFactorRow row, const Rgb& power);
  // A light's row over receivers of this solve (their indices), shot over the scene that holds
  // them and more: a cells solve's building, whose other rooms occlude too.
  using LightRowOver = std::function<FormFactorRow(int light, const std::vector<Patch>& receivers)>;
  // After every light's receiveLight, with --subdivide adaptive: the elements split where the
  // lights' direct light (powers[k] for light k) changes, and the children take it anew from
  // `again`, as the whole solve's first iteration splits and regathers; with --split-regather all,
  // every later split takes it anew too. Call before the first step.
  void splitAfterLights(std::vector<Rgb> powers, LightRowOver again);
  // Changes options().until and untilUnshot of the solve under way (throws OptionError).
  void setStoppingRule(double until, double untilUnshot);
  // Frees the form-factor cache's rows: a finished solve's bake needs none, and on a building they
  // are up to half its heap (building:6x6). Later shots fill it again.
  void dropFormFactorCache();
  // Frees the back end's scratch kept between shots (FormFactorBackend::releaseScratch): the next
  // step makes it again.
  void releaseScratch();
  double convergence() const;

  const Scene& scene() const;
  const std::vector<Patch>& patches() const;
  const std::vector<Rgb>& radiosity() const;  // B per patch, W/m^2
  std::vector<Rgb> displayRadiosity() const;  // B plus the display-only ambient term
  // The receivers (options().subdivide, solver/meshing/elements.h): the elements patches are cut
  // into, listed patch by patch; with subdivide off, the patches themselves. Each element's B
  // gathers what reaches it; a patch's B is the area mean of its elements'. Output (bake, render,
  // viewer) shows elements.
  const std::vector<Patch>& elements() const;
  const std::vector<Rgb>& elementRadiosity() const;  // B per element, W/m^2
  std::vector<Rgb> displayElementRadiosity() const;  // B per element plus the display-only ambient term
  std::vector<int> elementsOf(const std::vector<int>& patches) const;  // their elements, patch by patch
  const Ledger& ledger() const;
  const std::vector<IterationRecord>& history() const;
  // The options in force: as given, but with an analytic projection where occlusion is off.
  const SolveOptions& options() const;
  const EffectsPlan& effectsPlan() const;  // what is simulated and why

  SolverProgress progress() const;
  // Goes on from a progress of the same scene and options (and portal patches). Throws
  // std::invalid_argument, changing nothing, when its sizes are not this solve's.
  void restoreProgress(SolverProgress progress);

  // What the projection surface catches (closed form and sum of delta form factors).
  ProjectionSummary projectionSummary() const;
  // The back end computing form factors (e.g. for its single plane's item buffer).
  FormFactorBackend& backend();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace radmesh
