#pragma once
// The state of a ProgressiveSolver, shared by the files that implement it (progressive_solver.cpp,
// portal_power.cpp); private to solver/radiosity, not an interface.
#include <memory>
#include <optional>
#include <type_traits>
#include <vector>

#include "parallel/thread_pool.h"
#include "solver/formfactors/form_factor_cache.h"
#include "solver/formfactors/near_field.h"
#include "solver/meshing/elements.h"
#include "solver/radiosity/adaptive_split.h"
#include "solver/radiosity/progressive_solver.h"

namespace radmesh {
namespace solver_state {

using radmesh::channelSum;

// With colour off (a grey scene) one channel stands for three: `double` holds it, and these give
// bitwise what the three equal channels of an Rgb would (a + a + a rounds as 3a does).
inline double channelSum(double c) { return 3.0 * c; }
template <typename Value> Value channels(const Rgb& c);
template <> inline Rgb channels<Rgb>(const Rgb& c) { return c; }
template <> inline double channels<double>(const Rgb& c) { return c.r; }

}  // namespace solver_state

struct ProgressiveSolver::State {
  Scene scene;
  std::vector<Patch> patches;
  SolveOptions options;
  EffectsPlan plan;
  std::vector<Rgb> rho;
  std::vector<Rgb> radiosity;          // B
  std::vector<Rgb> unshotRadiosity;    // dB: received, not yet shot
  std::vector<double> unshotPowerW;    // dB * A summed over RGB, what shooter selection compares
  std::vector<int> timesShot;
  std::vector<int> emitters;           // the patches whose material emits
  std::vector<int> tieRank;            // shooters of equal power go in geometric order
  std::vector<Rgb> lightPower;         // per scene light, W per channel: all shot in iteration 1
  // Lights a cells solve shot over its building (splitAfterLights): their power, and their rows
  // over this solve's elements when they split. Empty: the lights are the scene's.
  std::vector<Rgb> buildingLightPower;
  ProgressiveSolver::LightRowOver buildingLightRow;
  int lightSplits = 0;  // elements splitAfterLights split: the first iteration's record counts them
  std::vector<char> isPortal;          // per patch (setPortalPatches); its elements are portal receivers
  int portalBinsN = 0;                 // setPortalPatches' n: directionBinCount(n) bins per portal patch
  // Per portal patch, per bin of its direction of travel (in the frame of its back, facing the
  // neighbour cell): arrived on it, waiting to be taken.
  std::vector<std::vector<Rgb>> portalPower;
  // Per portal patch with more than one bin: its unshot power (arrived from the neighbour) per bin.
  std::vector<std::vector<Rgb>> portalUnshot;
  std::unique_ptr<FormFactorBackend> backend;
  FormFactorCache cache;
  Ledger ledger;
  std::vector<IterationRecord> history;
  std::vector<FormFactorRow> rows;
  // Patches shoot, elements receive (options.subdivide; solver/meshing/elements.h): empty when off.
  Elements elements;
  std::optional<Occluders> occluders;  // the shadow criterion's, built at its first use
  std::vector<Rgb> elementRadiosity;
  std::optional<NearFieldFinder> elementNear;         // per shooter patch, its near elements
  std::vector<std::vector<NearFieldPair>> nearPairs;   // per shooter patch, as its rows reach them
  // Adaptive subdivision (adaptive_refinement.cpp): this iteration's shots, what each element
  // received from them (reflected, W/m^2 per channel), and each element's neighbours (kept across
  // splits: adjacency.neighbours).
  struct Shot {
    int patch = -1;  // the shooting patch, or -1 for scene light `light`
    int light = -1;
    Rgb power{0.0};
  };
  std::vector<Shot> shots;
  bool lightsShot = false;
  std::vector<Rgb> shotTotal;  // per patch: all it has shot (adaptive, --split-regather all)
  std::vector<Rgb> iterationGain;
  ElementAdjacency adjacency;
  double firstShotPowerW = 0.0;
  double convergence = 0.0;
  bool exhausted = false;

  State(const Scene& s, std::vector<Patch> p, const SolveOptions& o)
      : scene(s), patches(std::move(p)), options(o), cache(o.formFactorCacheBytes) {}

  std::vector<int> pickShooters();
  // What is left unshot is under --until-unshot (or under what the ledger can vouch for).
  bool littleLeft() const;
  // Whether an emitting patch has power and has not shot. The unshot stop waits for those: a dim
  // room's lamp, under --until-unshot of the building's power, would otherwise never shoot, and
  // its room stay black.
  bool waitsToShoot(int emitter) const;
  void fetchRows(const std::vector<int>& shooters, IterationRecord& record);
  void shoot(const std::vector<int>& shooters, IterationRecord& record);
  void shootLights(IterationRecord& record);
  void deliver(const FormFactorRow& row, const Rgb& power, bool fromLight = false);
  void deliverToReceivers(const FormFactorRow& row, const Rgb& power);
  void deliverByBins(const FormFactorRow& row, const std::vector<Rgb>& bins);
  void updateUnshot();
  void computeFreshRows(const std::vector<int>& shooters, std::vector<FormFactorRow>& computed);
  // The elements' near-field receivers to be found anew, as shooters ask (after elements are made
  // or read back; a split renumbers the finder instead: NearFieldFinder::receiversSplit), and every
  // shooter's pairs computed again.
  void findNearField();
  void refine(IterationRecord& record);
  // The lights regather takes anew: the scene's, or a cells solve's building's.
  const std::vector<Rgb>& regatheredLightPower() const { return buildingLightRow ? buildingLightPower : lightPower; }
  FormFactorRow lightRowOnElements(int light, ThreadPool& pool) const;
  void regather(const std::vector<int>& origin, const std::vector<char>& split,
                const std::vector<Rgb>& parentRadiosity, const std::vector<Rgb>& parentGain);
  template <typename Value, typename Incident> void receive(const FormFactorRow& row, Incident incidentOf);
  template <typename Value, typename Incident> void receiveOnElements(const FormFactorRow& row, Incident incidentOf);
  bool subdivided() const { return options.subdivide != Subdivide::Off; }
  bool adaptive() const { return options.subdivide == Subdivide::Adaptive; }
  const std::vector<Patch>& receivers() const { return subdivided() ? elements.elements : patches; }
  int patchOfReceiver(int r) const { return subdivided() ? elements.patchOf[r] : r; }
  bool portalReceiver(int r) const { return isPortal[patchOfReceiver(r)] != 0; }
  std::unique_ptr<FormFactorBackend> makeBackend() const;
  Rgb ambient() const;
  template <typename Incident> void passToPortals(const FormFactorRow& row, Incident incidentOf);
  void arrivalShares(int shooter, const Patch& portal, std::vector<double>& shares) const;
};

// Eq. 1.2 for one row, in three channels (Rgb) or in the one of a grey scene (double), each
// receiver updated where the back end keeps it.
template <typename Value, typename Incident>
void ProgressiveSolver::State::receive(const FormFactorRow& row, Incident incidentOf) {
  if (subdivided()) return receiveOnElements<Value>(row, incidentOf);
  // Per channel: incident, reflected, absorbed, gain, B, dB (6 flops); then the unshot power (a
  // channel sum and the area), the absorbed power (a channel sum) and the running sum (1). A grey
  // scene's channel sums are one multiply each.
  constexpr bool kColour = std::is_same_v<Value, Rgb>;
  constexpr double kFlops = kColour ? 3 * 6 + (2 + 1) + 2 + 1 : 6 + (1 + 1) + 1 + 1;
  ledger.absorbed += backend->updateReceivers(row, kFlops, [&](size_t r) {
    const int j = row.receivers[r];
    if (isPortal[j]) return 0.0;  // passToPortals took it
    const Value incident = incidentOf(r);
    const Value reflected = solver_state::channels<Value>(rho[j]) * incident;
    const Value gain = reflected / patches[j].areaM2;
    radiosity[j] += Rgb(gain);
    unshotRadiosity[j] += Rgb(gain);
    unshotPowerW[j] = solver_state::channelSum(solver_state::channels<Value>(unshotRadiosity[j])) * patches[j].areaM2;
    return solver_state::channelSum(incident - reflected);
  });
}

// Eq. 1.2 onto elements: B_e += rho_e dB_i F_ie A_i / A_e on the element's PE, then each patch
// gathers what its elements reflected (in receiver order, on the host: a patch's elements may lie
// on several PEs), as radiosity (the area mean of its elements') and as unshot power.
template <typename Value, typename Incident>
void ProgressiveSolver::State::receiveOnElements(const FormFactorRow& row, Incident incidentOf) {
  // Per channel: incident, reflected, absorbed, gain, B (5 flops); the absorbed power's channel
  // sum and the running sum.
  constexpr double kFlops = std::is_same_v<Value, Rgb> ? 3 * 5 + 2 + 1 : 5 + 1 + 1;
  std::vector<Value> reflected(row.receivers.size());
  ledger.absorbed += backend->updateReceivers(row, kFlops, [&](size_t r) {
    const int e = row.receivers[r];
    if (portalReceiver(e)) return 0.0;  // passToPortals took it
    const Value incident = incidentOf(r);
    reflected[r] = solver_state::channels<Value>(rho[elements.patchOf[e]]) * incident;
    elementRadiosity[e] += Rgb(reflected[r] / elements.elements[e].areaM2);
    if (adaptive()) iterationGain[e] += Rgb(reflected[r] / elements.elements[e].areaM2);
    return solver_state::channelSum(incident - reflected[r]);
  });
  for (size_t r = 0; r < row.receivers.size(); ++r) {
    const int j = elements.patchOf[row.receivers[r]];
    if (isPortal[j]) continue;
    const Value gain = reflected[r] / patches[j].areaM2;
    radiosity[j] += Rgb(gain);
    unshotRadiosity[j] += Rgb(gain);
    unshotPowerW[j] = solver_state::channelSum(solver_state::channels<Value>(unshotRadiosity[j])) * patches[j].areaM2;
  }
}

// What reaches a portal patch (its elements, when patches are cut into elements) waits there for
// the neighbour cell, in receiver order, by the bins of its direction of travel through the receiver.
template <typename Incident>
void ProgressiveSolver::State::passToPortals(const FormFactorRow& row, Incident incidentOf) {
  std::vector<double> shares;
  for (size_t r = 0; r < row.receivers.size(); ++r) {
    if (!portalReceiver(row.receivers[r])) continue;
    const int j = patchOfReceiver(row.receivers[r]);
    const Rgb incident = incidentOf(r);
    ledger.portalOut += solver_state::channelSum(incident);
    if (portalPower[j].size() == 1) {
      portalPower[j][0] += incident;
      continue;
    }
    arrivalShares(row.shooter, receivers()[row.receivers[r]], shares);
    for (size_t b = 0; b < shares.size(); ++b)
      if (shares[b] > 0.0) portalPower[j][b] += incident * shares[b];
  }
}

}  // namespace radmesh
