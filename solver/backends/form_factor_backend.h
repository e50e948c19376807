#pragma once
// The one interface between progressive refinement and whatever computes form factors: rows
// F_ij for given shooters. The native back end (host CPU) and the mesh back end (the emulated
// SIMD machine) implement it, as pbrt's cpu/ and gpu/ implement one integrator.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <span>
#include <vector>

#include "solver/formfactors/form_factor_row.h"
#include "solver/projection/item_buffer.h"
#include "solver/backends/shot_stats.h"
#include "solver/meshing/elements.h"
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
  // From now on, the rows of these shooters (portal patches) also split their directions into
  // directionBinCount(n) bins (FormFactorRow::binShares). Throws OptionError on a back end that
  // cannot: the base, for the mesh back end (its machine sums a pixel into its patch alone).
  virtual void binDirections(std::span<const int> shooters, int n);
  // The single plane's item buffer for a shooter, at the options' resolution and ratio, whatever
  // the projection in use: what the viewer shows, and where the back ends must agree pixel for pixel.
  virtual ItemBuffer singlePlaneItemBuffer(int shooter) = 0;
  // What the last iteration did on the back end's machine (shooter selection, the shot and the
  // radiosity update; the last computeRows alone when called outside one), on a back end that
  // reports it.
  virtual std::shared_ptr<const ShotStats> lastShotStats() const { return nullptr; }
  // The state a back end carries from shot to shot beyond the solver's, as opaque bytes for a
  // checkpoint (the mesh back end: the emulated machine's running cost counts, of which each
  // shot's costs are floating-point differences, so a resumed solve costs its shots bitwise as an
  // uninterrupted one does). Empty on a back end without any.
  virtual std::string machineState() const { return {}; }
  // Restores what machineState() gave; throws std::invalid_argument for bytes it did not write.
  virtual void restoreMachineState(const std::string& state);

  // The shooting-patch selection (the paper's reduceMax, k at a time): the k patches with the
  // most unshot power, strongest first, ties to the lower tie rank; patches without unshot power
  // are never chosen. Throws SolveError for a NaN power. Here on the host; the mesh back end
  // runs it on the machine and begins an iteration's record with it.
  virtual std::vector<int> selectShooters(std::span<const double> unshotPowerW, std::span<const int> tieRank,
                                          int k);
  // The radiosity update of one row: runs update(r) for every receiver r of the row and returns
  // the sum of what the calls return (the power they absorbed). Here in receiver order on the
  // host; the mesh back end runs each update on the PE holding the receiver, flopsPerUpdate
  // floating-point operations each, and sums by reduceAdd.
  virtual double updateReceivers(const FormFactorRow& row, double flopsPerUpdate,
                                 const std::function<double(std::size_t)>& update);

  // Adaptive subdivision (solver/radiosity/adaptive_refinement.cpp). A test of every receiver of
  // a row (the shadow criterion): runs test(r) for each receiver r, which returns the rays it cast
  // (0 for none). Here in receiver order on the host; the mesh back end runs each test on the PE
  // holding the receiver, flopsPerTest each, and as many ray steps as the busiest PE casts at
  // flopsPerRay each (SIMD: every PE steps through the most rays any PE casts).
  virtual void testReceivers(const FormFactorRow& row, double flopsPerTest, double flopsPerRay,
                             const std::function<int(std::size_t)>& test);
  // The gradient criterion (solver/radiosity/adaptive_split.h, markContrast) where the receivers
  // are held: marks split[e] = 1 for every receiver e with a neighbour whose reflected light differs
  // from its own by more than contrast times the brightest receiver's, where canSplit(e), and
  // returns true. Here false: the host holds the receivers and marks them itself. The mesh back end
  // marks them on its PEs (phase "gradient test").
  virtual bool markContrast(const std::vector<std::vector<int>>& /*neighbours*/,
                            const std::vector<double>& /*reflected*/, double /*contrast*/,
                            const std::function<bool(int)>& /*canSplit*/, std::vector<char>& /*split*/) {
    return false;
  }
  // The receivers (held by reference) were split in place: receiver e now is, or descends from,
  // old receiver origin[e]. The back end takes the new set (the mesh back end moves the element
  // records to their new PEs); rows from now on index the new receivers, as a back end made anew
  // for them would.
  virtual void receiversSplit(std::span<const int> origin) = 0;
  // Frees what the host keeps from one shot to the next, to be made again at the next shot (a cells
  // solve's cell between its turns). The mesh back end's memory is its machine's: it keeps it.
  virtual void releaseScratch() {}
};

// Throws SolveError naming the first patch whose unshot power is NaN: such a patch can neither be
// shot nor passed over without losing its power from the ledger.
void refuseNaNUnshotPower(std::span<const double> unshotPowerW);

// The back end options.backend names. Throws OptionError for one that is not available.
std::unique_ptr<FormFactorBackend> makeFormFactorBackend(const Scene& scene,
                                                         const std::vector<Patch>& patches,
                                                         const SolveOptions& options);
// The same, with patches shooting and their elements (solver/meshing/elements.h, held by
// reference: a split changes them in place) receiving: rows index elements.elements.
std::unique_ptr<FormFactorBackend> makeFormFactorBackend(const Scene& scene, const std::vector<Patch>& patches,
                                                         const Elements& elements, const SolveOptions& options);

}  // namespace radmesh
