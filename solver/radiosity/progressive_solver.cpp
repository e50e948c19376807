#include "solver/radiosity/progressive_solver.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "parallel/thread_pool.h"
#include "solver/formfactors/direction_bins.h"
#include "solver/formfactors/form_factor_cache.h"
#include "solver/formfactors/light_rows.h"
#include "solver/formfactors/near_field.h"
#include "solver/meshing/elements.h"
#include "solver/radiosity/adaptive_split.h"
#include "solver/projection/scan_conversion.h"
#include "solver/radiosity/progressive_solver_state.h"
#include "solver/radiosity/solver_input.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

using solver_state::channelSum;
using solver_state::channels;

ProgressiveSolver::ProgressiveSolver(const Scene& scene, std::vector<Patch> patches,
                                     const SolveOptions& options)
    : ProgressiveSolver(scene, std::move(patches), options, nullptr) {}

ProgressiveSolver::ProgressiveSolver(const Scene& scene, std::vector<Patch> patches, const SolveOptions& options,
                                     std::unique_ptr<FormFactorBackend> backend)
    : state_(std::make_unique<State>(scene, std::move(patches), options)) {
  validateOptions(options);
  checkAdaptiveMinElement(options);
  State& s = *state_;
  validateSolverInput(s.scene, s.patches);
  s.plan = planEffects(s.scene, s.patches, options.effects);
  // No occlusion: exact analytic form factors replace the item buffer (the mesh back end keeps its
  // plane, being the machine under study).
  if (!s.plan.occlusion && s.options.backend == Backend::Native) s.options.projection = Projection::Analytic;
  const size_t n = s.patches.size();
  if (s.subdivided()) {
    // Adaptive subdivision is refused where splitting everywhere could pass the uniform limit: a
    // tiny --min-element would otherwise refine shadow edges for hours (subdivideUniform checks its own).
    if (s.adaptive()) checkElementBudget(s.patches, true, options.minElementM);
    s.elements = s.adaptive() ? patchesAsElements(s.patches) : subdivideUniform(s.patches, options.minElementM);
    for (const Patch& e : s.elements.elements) s.elementRadiosity.push_back(s.scene.materials[e.material].emittance);
    if (s.adaptive()) s.adjacency = elementAdjacency(s.elements);
    if (s.adaptive()) s.shotTotal.assign(s.patches.size(), Rgb(0.0));
    // A cells solve's lights arrive before the first step (receiveLight): their gain counts too.
    if (s.adaptive()) s.iterationGain.assign(s.elements.elements.size(), Rgb(0.0));
  }
  s.findNearField();
  s.rho.resize(n);
  s.radiosity.resize(n);
  s.unshotRadiosity.resize(n);
  s.unshotPowerW.resize(n);
  s.timesShot.assign(n, 0);
  s.isPortal.assign(n, 0);
  s.portalPower.resize(n);
  s.portalUnshot.resize(n);
  for (size_t j = 0; j < n; ++j) {
    const Material& m = s.scene.materials[s.patches[j].material];
    s.rho[j] = m.rho;
    s.radiosity[j] = s.unshotRadiosity[j] = m.emittance;
    s.unshotPowerW[j] = channelSum(m.emittance) * s.patches[j].areaM2;
    s.ledger.emitted += s.unshotPowerW[j];
    if (m.emits()) s.emitters.push_back(static_cast<int>(j));
  }
  for (const Light& light : s.scene.lights) {
    s.lightPower.push_back(lightPower(s.scene, light));
    s.ledger.emitted += channelSum(s.lightPower.back());
  }
  s.ledger.unshot = s.ledger.emitted;
  s.exhausted = !(s.ledger.emitted > 0.0);
  s.tieRank = depthTieRanks(s.patches);
  s.backend = backend ? std::move(backend) : s.makeBackend();
}

// The back end over the receivers, with the portal patches' rows split by direction bin.
std::unique_ptr<FormFactorBackend> ProgressiveSolver::State::makeBackend() const {
  std::unique_ptr<FormFactorBackend> made = subdivided() ? makeFormFactorBackend(scene, patches, elements, options)
                                                         : makeFormFactorBackend(scene, patches, options);
  std::vector<int> portals;
  for (size_t j = 0; j < patches.size(); ++j)
    if (isPortal[j]) portals.push_back(static_cast<int>(j));
  if (directionBinCount(portalBinsN) > 1 && !portals.empty()) made->binDirections(portals, portalBinsN);
  return made;
}

ProgressiveSolver::~ProgressiveSolver() = default;

// The k patches with the most unshot power, on the back end (the mesh's reduceMax). Without
// interreflection, every emitter at once: nothing comes back, so one shot each from the first
// state is the whole solution. Once the rest is under the unshot stop, the emitters that have not
// shot yet, strongest first: the same selection over their power alone, charged to the machine.
std::vector<int> ProgressiveSolver::State::pickShooters() {
  const int k = plan.interreflection ? options.shooters : static_cast<int>(patches.size());
  if (options.untilUnshot > 0.0 && littleLeft()) {
    std::vector<double> waitingW(unshotPowerW.size(), 0.0);
    bool waiting = false;
    for (int i : emitters)
      if (waitsToShoot(i)) waitingW[i] = unshotPowerW[i], waiting = true;
    if (waiting) return backend->selectShooters(waitingW, tieRank, k);
  }
  return backend->selectShooters(unshotPowerW, tieRank, k);
}

bool ProgressiveSolver::State::littleLeft() const {
  // Below kLedgerTolerance the unshot power is rounding the ledger cannot vouch for: shooting it
  // would only wait for C to round to 1.
  return ledger.unshotFraction() <= std::max(options.untilUnshot, kLedgerTolerance);
}

bool ProgressiveSolver::State::waitsToShoot(int emitter) const {
  return timesShot[emitter] == 0 && unshotPowerW[emitter] > 0.0;
}

void ProgressiveSolver::State::fetchRows(const std::vector<int>& shooters, IterationRecord& record) {
  rows.resize(shooters.size());
  std::vector<int> missing;
  std::vector<size_t> missingSlot;
  for (size_t s = 0; s < shooters.size(); ++s) {
    if (timesShot[shooters[s]] > 0) ++record.reusedRows;
    if (const FormFactorRow* row = cache.find(shooters[s])) {
      rows[s] = *row;
      rows[s].reused = true;
      ++record.cacheHits;
    } else {
      missing.push_back(shooters[s]);
      missingSlot.push_back(s);
    }
  }
  if (missing.empty()) return;
  std::vector<FormFactorRow> computed;
  computeFreshRows(missing, computed);
  for (size_t m = 0; m < missing.size(); ++m) {
    if (options.formFactorCacheBytes > 0) cache.insert(computed[m]);
    rows[missingSlot[m]] = std::move(computed[m]);
  }
}

// Rows from the back end, corrected in the near field.
void ProgressiveSolver::State::computeFreshRows(const std::vector<int>& shooters, std::vector<FormFactorRow>& computed) {
  backend->computeRows(shooters, computed);
  if (plan.nearField)
    for (FormFactorRow& row : computed) {
      const std::vector<int>& near =
          subdivided() ? elementNear->receiversNear(row.shooter) : plan.nearReceivers[row.shooter];
      std::vector<NearFieldPair>& pairs = nearPairs[row.shooter];
      completeNearFieldPairs(patches[row.shooter], receivers(), near, row, pairs);
      correctNearField(row, near, pairs);
    }
}

void ProgressiveSolver::State::findNearField() {
  if (plan.nearField && subdivided()) elementNear.emplace(patches, elements.elements);
  nearPairs.assign(patches.size(), {});
}

// Eq. 1.2 for every shooter, all from the same state: B_j += dB_i rho_j F_ij A_i / A_j.
void ProgressiveSolver::State::shoot(const std::vector<int>& shooters, IterationRecord& record) {
  std::vector<Rgb> shotPower(shooters.size());
  for (size_t s = 0; s < shooters.size(); ++s) {
    const int i = shooters[s];
    shotPower[s] = unshotRadiosity[i] * patches[i].areaM2;
    unshotRadiosity[i] = Rgb(0.0);
    unshotPowerW[i] = 0.0;
    ++timesShot[i];
    record.shotPowerW += channelSum(shotPower[s]);
    shots.push_back({i, -1, shotPower[s]});
    if (adaptive()) shotTotal[i] += shotPower[s];
  }
  for (size_t s = 0; s < shooters.size(); ++s) {
    std::vector<Rgb>& bins = portalUnshot[shooters[s]];
    if (bins.empty()) {
      deliver(rows[s], shotPower[s]);
    } else {
      deliverByBins(rows[s], bins);
      std::fill(bins.begin(), bins.end(), Rgb(0.0));
    }
  }
  updateUnshot();
  record.capturedFraction = rows.empty() ? 0.0 : rows.front().capturedFraction;
}

// Iteration 1 of a scene with lights: each light's one shot, all from the first state. Their rows
// are computed on the host for every back end (solver/formfactors/light_rows.h); what they send
// past the model or onto its outside never entered it (Ledger::lightOutside).
void ProgressiveSolver::State::shootLights(IterationRecord& record) {
  ThreadPool pool(options.threads);
  LightRows rows(scene, receivers(), options.resolution, sceneNearDepth(patches), pool);
  for (size_t k = 0; k < scene.lights.size(); ++k) {
    if (!(channelSum(lightPower[k]) > 0.0)) continue;  // a dark light, or a beam with no window
    const FormFactorRow row = rows.row(scene.lights[k]);
    deliver(row, lightPower[k], true);
    shots.push_back({-1, static_cast<int>(k), lightPower[k]});
    record.shotPowerW += channelSum(lightPower[k]);
  }
  lightsShot = true;
  updateUnshot();
  record.capturedFraction = 1.0;
}

// Where one row's power goes: not captured, escaped, the backs of one-sided patches, and the
// receivers (eq. 1.2, or absorbed outright when nothing reflects). Escape is booked in a closed
// scene too: pixel centres on a seam where patch edges meet in a T-junction may fall outside
// both sides by rounding, and that light hits nothing (EffectsPlan::escape).
void ProgressiveSolver::State::deliver(const FormFactorRow& row, const Rgb& power, bool fromLight) {
  bookShotLosses(ledger, row, channelSum(power), fromLight);
  deliverToReceivers(row, power);
}

// The part of a row's power that lands on the fronts of its receivers.
void ProgressiveSolver::State::deliverToReceivers(const FormFactorRow& row, const Rgb& power) {
  const double powerW = channelSum(power);
  passToPortals(row, [&](size_t r) { return power * row.formFactors[r]; });
  if (!plan.interreflection) {  // black receivers: B stays as emitted, all that arrives is absorbed
    double received = 0.0;
    for (size_t r = 0; r < row.receivers.size(); ++r)
      if (!portalReceiver(row.receivers[r])) received += row.formFactors[r];
    ledger.absorbed += powerW * received;
  } else if (plan.colour) {
    receive<Rgb>(row, [&](size_t r) { return power * row.formFactors[r]; });
  } else {
    receive<double>(row, [&](size_t r) { return power.r * row.formFactors[r]; });
  }
}

void ProgressiveSolver::State::updateUnshot() {
  ledger.unshot = 0.0;
  for (double p : unshotPowerW) ledger.unshot += p;
}

const IterationRecord& ProgressiveSolver::step() {
  State& s = *state_;
  if (s.exhausted && !s.history.empty()) return s.history.back();
  const auto start = std::chrono::steady_clock::now();

  IterationRecord record;
  record.iteration = static_cast<int>(s.history.size()) + 1;
  s.shots.clear();
  if (s.adaptive()) s.iterationGain.assign(s.elements.elements.size(), Rgb(0.0));
  if (s.history.empty()) record.elementsSplit = s.lightSplits;
  if (s.history.empty() && !s.scene.lights.empty()) {
    // The lights shoot first, once: C is measured against the strongest of them and the emitters.
    s.firstShotPowerW = *std::max_element(s.unshotPowerW.begin(), s.unshotPowerW.end());
    for (const Rgb& power : s.lightPower) s.firstShotPowerW = std::max(s.firstShotPowerW, channelSum(power));
    s.shootLights(record);
    s.convergence = 0.0;
  } else if (record.shooters = s.pickShooters(); !record.shooters.empty()) {
    // C_i = 1 - s_i / s_1 (the paper's section 1.6), s_i the strongest shooter's power.
    const double strongestW = s.unshotPowerW[record.shooters.front()];
    if (s.firstShotPowerW == 0.0) s.firstShotPowerW = strongestW;
    s.fetchRows(record.shooters, record);
    s.shoot(record.shooters, record);
    s.convergence = 1.0 - strongestW / s.firstShotPowerW;
  }
  if (s.adaptive()) s.refine(record);
  s.exhausted = std::none_of(s.unshotPowerW.begin(), s.unshotPowerW.end(), [](double p) { return p > 0.0; });
  if (s.exhausted) s.convergence = 1.0;  // nothing is left to shoot: the solution is exact

  record.reusedRowsTotal = record.reusedRows + (s.history.empty() ? 0 : s.history.back().reusedRowsTotal);
  record.convergence = s.convergence;
  record.ledger = s.ledger;
  checkLedger(s.ledger, record.iteration);
  record.shotStats = s.backend->lastShotStats();
  record.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  s.history.push_back(std::move(record));
  return s.history.back();
}

bool ProgressiveSolver::done() const {
  const State& s = *state_;
  const bool littleLeft = s.littleLeft() && (s.options.untilUnshot == 0.0 || emittersToShoot() == 0);
  return s.exhausted || s.convergence >= s.options.until || littleLeft ||
         static_cast<int>(s.history.size()) >= s.options.maxIterations;
}

bool ProgressiveSolver::exhausted() const { return state_->exhausted; }

int ProgressiveSolver::emittersToShoot() const {
  const State& s = *state_;  // a count, asked every round of a cells solve: no list, no sort
  return static_cast<int>(std::count_if(s.emitters.begin(), s.emitters.end(), [&](int i) { return s.waitsToShoot(i); }));
}

double ProgressiveSolver::receiveLight(FormFactorRow row, const Rgb& power) {
  State& s = *state_;
  for (int j : row.receivers)
    if (j < 0 || static_cast<size_t>(j) >= s.receivers().size())
      throw std::invalid_argument(fmt::format("light receiver {} is not one of the {} receivers", j, s.receivers().size()));
  row.backFaces = 0.0;  // what missed, escaped or hit a back face is the caller's to book
  const double arrivedW = channelSum(power) * row.hitFraction();
  s.ledger.emitted += arrivedW;
  s.deliverToReceivers(row, power);
  s.updateUnshot();
  s.exhausted = std::none_of(s.unshotPowerW.begin(), s.unshotPowerW.end(), [](double p) { return p > 0.0; });
  checkLedger(s.ledger, 0);
  return arrivedW;
}

void ProgressiveSolver::setStoppingRule(double until, double untilUnshot) {
  SolveOptions changed = state_->options;
  changed.until = until;
  changed.untilUnshot = untilUnshot;
  validateOptions(changed);
  state_->options = changed;
}

void ProgressiveSolver::releaseScratch() { state_->backend->releaseScratch(); }

void ProgressiveSolver::dropFormFactorCache() { state_->cache = FormFactorCache(state_->options.formFactorCacheBytes); }

double ProgressiveSolver::convergence() const { return state_->convergence; }
const Scene& ProgressiveSolver::scene() const { return state_->scene; }
const std::vector<Patch>& ProgressiveSolver::patches() const { return state_->patches; }
const std::vector<Rgb>& ProgressiveSolver::radiosity() const { return state_->radiosity; }
const std::vector<Patch>& ProgressiveSolver::elements() const { return state_->receivers(); }
const std::vector<Rgb>& ProgressiveSolver::elementRadiosity() const {
  return state_->subdivided() ? state_->elementRadiosity : state_->radiosity;
}
const Ledger& ProgressiveSolver::ledger() const { return state_->ledger; }
const std::vector<IterationRecord>& ProgressiveSolver::history() const { return state_->history; }
const SolveOptions& ProgressiveSolver::options() const { return state_->options; }
const EffectsPlan& ProgressiveSolver::effectsPlan() const { return state_->plan; }
ProjectionSummary ProgressiveSolver::projectionSummary() const { return state_->backend->projectionSummary(); }
FormFactorBackend& ProgressiveSolver::backend() { return *state_->backend; }

// The ambient term of Cohen et al. 1988: the unshot power, spread evenly and interreflected with
// the area-averaged reflectance, added for display only (it is not in the ledger). Cohen's scenes
// were closed; here the fraction of shot power lost so far (escaped through openings, or missed
// by the single plane) is lost from the unshot power too, at every bounce, as it will be when it
// is shot. Without that, an open room shows brighter than it will converge to.
Rgb ProgressiveSolver::State::ambient() const {
  if (!options.ambient) return Rgb(0.0);
  Rgb unshotPower(0.0), rhoArea(0.0);
  double area = 0.0;
  for (size_t j = 0; j < patches.size(); ++j) {
    unshotPower += unshotRadiosity[j] * patches[j].areaM2;
    rhoArea += rho[j] * patches[j].areaM2;
    area += patches[j].areaM2;
  }
  const Ledger& l = ledger;
  // A cell's light leaving through its portals is lost to it as escaped light is.
  const double shot = l.input() - l.unshot;  // = absorbed + not captured + escaped + portal out
  const double lost = l.escaped + l.notCaptured + l.portalOut;
  const double kept = shot > 0.0 ? std::clamp(1.0 - lost / shot, 0.0, 1.0) : 1.0;
  const Rgb averageRho = rhoArea / area;
  return unshotPower * kept / area / (Rgb(1.0) - averageRho * kept);
}

std::vector<Rgb> ProgressiveSolver::displayRadiosity() const {
  const State& s = *state_;
  if (!s.options.ambient) return s.radiosity;
  const Rgb ambient = s.ambient();
  std::vector<Rgb> shown(s.radiosity);
  for (size_t j = 0; j < shown.size(); ++j) shown[j] += s.rho[j] * ambient;
  return shown;
}

std::vector<int> ProgressiveSolver::elementsOf(const std::vector<int>& patches) const {
  const State& s = *state_;
  if (!s.subdivided()) return patches;
  std::vector<int> elements;
  for (int p : patches)
    for (int e = s.elements.first.at(static_cast<size_t>(p)); e < s.elements.first.at(static_cast<size_t>(p) + 1); ++e)
      elements.push_back(e);
  return elements;
}

std::vector<Rgb> ProgressiveSolver::displayElementRadiosity() const {
  const State& s = *state_;
  if (!s.subdivided()) return displayRadiosity();
  if (!s.options.ambient) return s.elementRadiosity;
  const Rgb ambient = s.ambient();
  std::vector<Rgb> shown(s.elementRadiosity);
  for (size_t e = 0; e < shown.size(); ++e) shown[e] += s.rho[s.elements.patchOf[e]] * ambient;
  return shown;
}

}  // namespace radmesh
