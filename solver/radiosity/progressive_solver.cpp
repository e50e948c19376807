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
#include "solver/projection/scan_conversion.h"
#include "solver/radiosity/solver_input.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

namespace {

double channelSum(const Rgb& c) { return c.r + c.g + c.b; }

// With colour off (a grey scene) one channel stands for three: `double` holds it, and these give
// bitwise what the three equal channels of an Rgb would (a + a + a rounds as 3a does).
double channelSum(double c) { return 3.0 * c; }
template <typename Value> Value channels(const Rgb& c);
template <> Rgb channels<Rgb>(const Rgb& c) { return c; }
template <> double channels<double>(const Rgb& c) { return c.r; }

// Whether a progress has n patches and `elements` elements (0: patches receive) and names no
// others (a row's shooter and receivers, a record's shooters).
bool fitsPatches(const SolverProgress& p, size_t n, size_t elements) {
  auto patchIndex = [n](int j) { return j >= 0 && static_cast<size_t>(j) < n; };
  const size_t receivers = elements > 0 ? elements : n;
  auto receiverIndex = [receivers](int j) { return j >= 0 && static_cast<size_t>(j) < receivers; };
  auto rowFits = [&](const FormFactorRow& row) {
    return patchIndex(row.shooter) && row.receivers.size() == row.formFactors.size() &&
           std::all_of(row.receivers.begin(), row.receivers.end(), receiverIndex);
  };
  auto recordFits = [&](const IterationRecord& r) { return std::all_of(r.shooters.begin(), r.shooters.end(), patchIndex); };
  return p.radiosity.size() == n && p.unshotRadiosity.size() == n && p.unshotPowerW.size() == n &&
         p.elementRadiosity.size() == elements &&
         p.timesShot.size() == n && std::all_of(p.cachedRows.begin(), p.cachedRows.end(), rowFits) &&
         std::all_of(p.history.begin(), p.history.end(), recordFits);
}

}  // namespace

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
  std::vector<int> tieRank;            // shooters of equal power go in geometric order
  std::vector<Rgb> lightPower;         // per scene light, W per channel: all shot in iteration 1
  std::vector<char> isPortal;          // per patch (setPortalPatches)
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
  std::vector<Rgb> elementRadiosity;
  std::vector<std::vector<int>> elementNearReceivers;  // per shooter patch, its near elements
  double firstShotPowerW = 0.0;
  double convergence = 0.0;
  bool exhausted = false;

  State(const Scene& s, std::vector<Patch> p, const SolveOptions& o)
      : scene(s), patches(std::move(p)), options(o), cache(o.formFactorCacheBytes) {}

  std::vector<int> pickShooters();
  void fetchRows(const std::vector<int>& shooters, IterationRecord& record);
  void shoot(const std::vector<int>& shooters, IterationRecord& record);
  void shootLights(IterationRecord& record);
  void deliver(const FormFactorRow& row, const Rgb& power);
  void deliverToReceivers(const FormFactorRow& row, const Rgb& power);
  void deliverByBins(const FormFactorRow& row, const std::vector<Rgb>& bins);
  void updateUnshot();
  template <typename Value, typename Incident> void receive(const FormFactorRow& row, Incident incidentOf);
  template <typename Value, typename Incident> void receiveOnElements(const FormFactorRow& row, Incident incidentOf);
  bool subdivided() const { return options.subdivide != Subdivide::Off; }
  const std::vector<Patch>& receivers() const { return subdivided() ? elements.elements : patches; }
  Rgb ambient() const;
  template <typename Incident> void passToPortals(const FormFactorRow& row, Incident incidentOf);
  void arrivalShares(int shooter, int portal, std::vector<double>& shares) const;
};

ProgressiveSolver::ProgressiveSolver(const Scene& scene, std::vector<Patch> patches,
                                     const SolveOptions& options)
    : ProgressiveSolver(scene, std::move(patches), options, nullptr) {}

ProgressiveSolver::ProgressiveSolver(const Scene& scene, std::vector<Patch> patches, const SolveOptions& options,
                                     std::unique_ptr<FormFactorBackend> backend)
    : state_(std::make_unique<State>(scene, std::move(patches), options)) {
  validateOptions(options);
  State& s = *state_;
  validateSolverInput(s.scene, s.patches);
  s.plan = planEffects(s.scene, s.patches, options.effects);
  // No occlusion: exact analytic form factors replace the item buffer (the mesh back end keeps its
  // plane, being the machine under study).
  if (!s.plan.occlusion && s.options.backend == Backend::Native) s.options.projection = Projection::Analytic;
  const size_t n = s.patches.size();
  if (s.subdivided()) {
    s.elements = subdivideUniform(s.patches, options.minElementM);
    for (const Patch& e : s.elements.elements) s.elementRadiosity.push_back(s.scene.materials[e.material].emittance);
    if (s.plan.nearField) s.elementNearReceivers = findNearFieldReceivers(s.patches, s.elements.elements);
  }
  s.rho.resize(n);
  s.radiosity.resize(n);
  s.unshotRadiosity.resize(n);
  s.unshotPowerW.resize(n);
  s.timesShot.assign(n, 0);
  s.isPortal.assign(s.receivers().size(), 0);
  s.portalPower.resize(n);
  s.portalUnshot.resize(n);
  for (size_t j = 0; j < n; ++j) {
    const Material& m = s.scene.materials[s.patches[j].material];
    s.rho[j] = m.rho;
    s.radiosity[j] = s.unshotRadiosity[j] = m.emittance;
    s.unshotPowerW[j] = channelSum(m.emittance) * s.patches[j].areaM2;
    s.ledger.emitted += s.unshotPowerW[j];
  }
  for (const Light& light : s.scene.lights) {
    s.lightPower.push_back(lightPower(s.scene, light));
    s.ledger.emitted += channelSum(s.lightPower.back());
  }
  s.ledger.unshot = s.ledger.emitted;
  s.exhausted = !(s.ledger.emitted > 0.0);
  s.tieRank = depthTieRanks(s.patches);
  s.backend = backend ? std::move(backend) : makeFormFactorBackend(s.scene, s.patches, s.receivers(), s.options);
}

ProgressiveSolver::~ProgressiveSolver() = default;

// The k patches with the most unshot power, on the back end (the mesh's reduceMax). Without
// interreflection, every emitter at once: nothing comes back, so one shot each from the first
// state is the whole solution.
std::vector<int> ProgressiveSolver::State::pickShooters() {
  const int k = plan.interreflection ? options.shooters : static_cast<int>(patches.size());
  return backend->selectShooters(unshotPowerW, tieRank, k);
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
  backend->computeRows(missing, computed);
  if (plan.nearField)
    for (FormFactorRow& row : computed) {
      if (subdivided())
        correctNearField(row, patches[row.shooter], elements.elements, elementNearReceivers[row.shooter]);
      else
        correctNearField(row, patches, plan.nearReceivers[row.shooter]);
    }
  for (size_t m = 0; m < missing.size(); ++m) {
    if (options.formFactorCacheBytes > 0) cache.insert(computed[m]);
    rows[missingSlot[m]] = std::move(computed[m]);
  }
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
  const double nearDepth = sceneNearDepth(patches);
  for (size_t k = 0; k < scene.lights.size(); ++k) {
    if (!(channelSum(lightPower[k]) > 0.0)) continue;  // a dark light, or a beam with no window
    const FormFactorRow row = lightRow(scene, scene.lights[k], receivers(), options.resolution, nearDepth, pool);
    deliver(row, lightPower[k]);
    ledger.lightOutside += channelSum(lightPower[k]) * (row.escapedFraction() + row.backFaces);
    record.shotPowerW += channelSum(lightPower[k]);
  }
  updateUnshot();
  record.capturedFraction = 1.0;
}

// Where one row's power goes: not captured, escaped, the backs of one-sided patches, and the
// receivers (eq. 1.2, or absorbed outright when nothing reflects). Escape is booked in a closed
// scene too: pixel centres on a seam where patch edges meet in a T-junction may fall outside
// both sides by rounding, and that light hits nothing (EffectsPlan::escape).
void ProgressiveSolver::State::deliver(const FormFactorRow& row, const Rgb& power) {
  const double powerW = channelSum(power);
  ledger.notCaptured += powerW * (1.0 - row.capturedFraction);
  ledger.escaped += powerW * row.escapedFraction();
  ledger.absorbed += powerW * row.backFaces;
  ledger.absorbedByBackFaces += powerW * row.backFaces;
  deliverToReceivers(row, power);
}

// The part of a row's power that lands on the fronts of its receivers.
void ProgressiveSolver::State::deliverToReceivers(const FormFactorRow& row, const Rgb& power) {
  const double powerW = channelSum(power);
  passToPortals(row, [&](size_t r) { return power * row.formFactors[r]; });
  if (!plan.interreflection) {  // black receivers: B stays as emitted, all that arrives is absorbed
    double received = 0.0;
    for (size_t r = 0; r < row.receivers.size(); ++r)
      if (!isPortal[row.receivers[r]]) received += row.formFactors[r];
    ledger.absorbed += powerW * received;
  } else if (plan.colour) {
    receive<Rgb>(row, [&](size_t r) { return power * row.formFactors[r]; });
  } else {
    receive<double>(row, [&](size_t r) { return power.r * row.formFactors[r]; });
  }
}

// A portal patch's shot, each bin's power into its own directions: sum_b P_b F_jb / F_b to
// receiver j. A bin the projection does not cover (F_b = 0: the single plane's grazing bins) is
// shot diffusely with the whole row, as a portal without bins would be.
void ProgressiveSolver::State::deliverByBins(const FormFactorRow& row, const std::vector<Rgb>& bins) {
  std::vector<double> hit(row.binBackFaces);  // per bin: landing on a patch, front or back
  for (const FormFactorRow::BinShare& share : row.binShares) hit[share.bin] += share.formFactor;
  std::vector<Rgb> perFormFactor(bins.size(), Rgb(0.0));  // P_b / F_b
  Rgb uncovered(0.0);
  for (size_t b = 0; b < bins.size(); ++b) {
    const double total = row.binTotals[b];
    if (!(total > 0.0)) {
      uncovered += bins[b];
      continue;
    }
    perFormFactor[b] = bins[b] / total;
    const double backW = channelSum(perFormFactor[b]) * row.binBackFaces[b];
    ledger.absorbed += backW;
    ledger.absorbedByBackFaces += backW;
    const double escaped = total - hit[b];  // as FormFactorRow::escapedFraction, per bin
    if (escaped > 1e-12 * total) ledger.escaped += channelSum(perFormFactor[b]) * escaped;
  }
  // The receivers of the bins as a row of their own, each with the power reaching it.
  FormFactorRow lit;
  lit.shooter = row.shooter;
  std::vector<Rgb> incident;
  for (const FormFactorRow::BinShare& share : row.binShares) {
    if (lit.receivers.empty() || lit.receivers.back() != share.patch) {
      lit.receivers.push_back(share.patch);
      incident.push_back(Rgb(0.0));
    }
    incident.back() += perFormFactor[share.bin] * share.formFactor;
  }
  lit.formFactors.assign(lit.receivers.size(), 0.0);
  auto incidentOf = [&](size_t r) { return incident[r]; };
  passToPortals(lit, incidentOf);
  if (!plan.interreflection) {
    for (size_t r = 0; r < lit.receivers.size(); ++r)
      if (!isPortal[lit.receivers[r]]) ledger.absorbed += channelSum(incident[r]);
  } else {
    receive<Rgb>(lit, incidentOf);
  }
  if (channelSum(uncovered) > 0.0) deliver(row, uncovered);
}

void ProgressiveSolver::State::updateUnshot() {
  ledger.unshot = 0.0;
  for (double p : unshotPowerW) ledger.unshot += p;
}

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
    const Value reflected = channels<Value>(rho[j]) * incident;
    const Value gain = reflected / patches[j].areaM2;
    radiosity[j] += Rgb(gain);
    unshotRadiosity[j] += Rgb(gain);
    unshotPowerW[j] = channelSum(channels<Value>(unshotRadiosity[j])) * patches[j].areaM2;
    return channelSum(incident - reflected);
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
    const Value incident = incidentOf(r);
    reflected[r] = channels<Value>(rho[elements.patchOf[e]]) * incident;
    elementRadiosity[e] += Rgb(reflected[r] / elements.elements[e].areaM2);
    return channelSum(incident - reflected[r]);
  });
  for (size_t r = 0; r < row.receivers.size(); ++r) {
    const int j = elements.patchOf[row.receivers[r]];
    const Value gain = reflected[r] / patches[j].areaM2;
    radiosity[j] += Rgb(gain);
    unshotRadiosity[j] += Rgb(gain);
    unshotPowerW[j] = channelSum(channels<Value>(unshotRadiosity[j])) * patches[j].areaM2;
  }
}

// What reaches a portal patch waits there for the neighbour cell, in receiver order, by the bins of
// its direction of travel.
template <typename Incident>
void ProgressiveSolver::State::passToPortals(const FormFactorRow& row, Incident incidentOf) {
  std::vector<double> shares;
  for (size_t r = 0; r < row.receivers.size(); ++r) {
    const int j = row.receivers[r];
    if (!isPortal[j]) continue;
    const Rgb incident = incidentOf(r);
    ledger.portalOut += channelSum(incident);
    if (portalPower[j].size() == 1) {
      portalPower[j][0] += incident;
      continue;
    }
    arrivalShares(row.shooter, j, shares);
    for (size_t b = 0; b < shares.size(); ++b)
      if (shares[b] > 0.0) portalPower[j][b] += incident * shares[b];
  }
}

// How what reaches a portal patch from a shooter splits over the bins of its direction of travel,
// in the frame of the portal's back (the twin patch facing into the neighbour cell: u, -v, -n),
// where the light goes on: the directions from the shooter's centre through the patch, each bin's
// part weighted by its cosine to the portal's normal (which for a patch small against its distance
// is the shooter's cosine up to a constant), the shares adding up to 1.
void ProgressiveSolver::State::arrivalShares(int shooter, int portal, std::vector<double>& shares) const {
  const Patch& p = patches[portal];
  std::array<Vec3, 4> seen{};
  for (int k = 0; k < p.vertexCount; ++k) {
    const Vec3 d = p.vertices[k] - patches[shooter].centroid;
    seen[k] = Vec3(glm::dot(d, p.frame.u), -glm::dot(d, p.frame.v), -glm::dot(d, p.frame.n));
  }
  shares.assign(directionBinCount(portalBinsN), 0.0);
  double total = 0.0;
  splitOverDirectionBins(portalBinsN, std::span<const Vec3>(seen.data(), p.vertexCount), [&](int b, double f) {
    shares[b] += f;
    total += f;
  });
  if (!(total > 0.0)) {  // seen edge-on: the direction of its centre
    const Vec3 d = p.centroid - patches[shooter].centroid;
    shares[directionBin(portalBinsN, Vec3(glm::dot(d, p.frame.u), -glm::dot(d, p.frame.v), -glm::dot(d, p.frame.n)))] = 1.0;
    return;
  }
  for (double& share : shares) share /= total;
}

const IterationRecord& ProgressiveSolver::step() {
  State& s = *state_;
  if (s.exhausted && !s.history.empty()) return s.history.back();
  const auto start = std::chrono::steady_clock::now();

  IterationRecord record;
  record.iteration = static_cast<int>(s.history.size()) + 1;
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
  const bool littleLeft = s.options.untilUnshot > 0.0 && s.ledger.unshotFraction() <= s.options.untilUnshot;
  return s.exhausted || s.convergence >= s.options.until || littleLeft ||
         static_cast<int>(s.history.size()) >= s.options.maxIterations;
}

bool ProgressiveSolver::exhausted() const { return state_->exhausted; }

void ProgressiveSolver::setPortalPatches(const std::vector<int>& portalPatches, int binsN) {
  State& s = *state_;
  if (s.subdivided() && !portalPatches.empty())
    throw OptionError("portal patches need patches that receive: a solve whose elements receive (subdivide) cannot "
                      "be a cell yet");
  for (int j : portalPatches)
    if (j < 0 || static_cast<size_t>(j) >= s.patches.size())
      throw std::invalid_argument(fmt::format("portal patch {} is not one of the {} patches", j, s.patches.size()));
  const int bins = directionBinCount(binsN);
  if (bins > 1) s.backend->binDirections(portalPatches, binsN);
  s.portalBinsN = binsN;
  for (int j : portalPatches) {
    s.isPortal[j] = 1;
    s.portalPower[j].assign(bins, Rgb(0.0));
    if (bins > 1) s.portalUnshot[j].assign(bins, Rgb(0.0));
  }
}

Rgb ProgressiveSolver::portalPower(int patch) const {
  Rgb sum(0.0);
  for (const Rgb& bin : state_->portalPower.at(static_cast<size_t>(patch))) sum += bin;
  return sum;
}

std::vector<Rgb> ProgressiveSolver::takePortalPower(int patch) {
  std::vector<Rgb>& bins = state_->portalPower.at(static_cast<size_t>(patch));
  return std::exchange(bins, std::vector<Rgb>(bins.size(), Rgb(0.0)));
}

void ProgressiveSolver::addPortalPower(int patch, std::span<const Rgb> bins) {
  State& s = *state_;
  const size_t j = static_cast<size_t>(patch);
  if (!s.isPortal.at(j) || bins.size() != s.portalPower[j].size())
    throw std::invalid_argument(fmt::format("patch {} is not a portal patch of {} direction bins", patch, bins.size()));
  Rgb power(0.0);
  for (const Rgb& bin : bins) power += bin;
  const double powerW = channelSum(power);
  if (!(powerW > 0.0)) return;
  if (!s.portalUnshot[j].empty())
    for (size_t b = 0; b < bins.size(); ++b) s.portalUnshot[j][b] += bins[b];
  s.unshotRadiosity.at(j) += power / s.patches[j].areaM2;
  const double before = s.unshotPowerW[j];
  s.unshotPowerW[j] = channelSum(s.unshotRadiosity[j]) * s.patches[j].areaM2;
  s.ledger.portalIn += powerW;
  s.ledger.unshot += s.unshotPowerW[j] - before;
  s.exhausted = false;
}

double ProgressiveSolver::receiveLight(FormFactorRow row, const Rgb& power) {
  State& s = *state_;
  for (int j : row.receivers)
    if (j < 0 || static_cast<size_t>(j) >= s.patches.size())
      throw std::invalid_argument(fmt::format("light receiver {} is not one of the {} patches", j, s.patches.size()));
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
SolverProgress ProgressiveSolver::progress() const {
  const State& s = *state_;
  return {s.radiosity, s.unshotRadiosity, s.unshotPowerW, s.timesShot, s.ledger, s.history,
          s.firstShotPowerW, s.convergence, s.exhausted, s.backend->machineState(), s.cache.contents(),
          s.elementRadiosity};
}

void ProgressiveSolver::restoreProgress(SolverProgress p) {
  State& s = *state_;
  const size_t n = s.patches.size();
  if (!fitsPatches(p, n, s.elementRadiosity.size()) || p.machineState.empty() != s.backend->machineState().empty())
    throw std::invalid_argument(fmt::format(
        "solver progress of another solve: not {} patches, shooters of other patches, or another back end", n));
  s.backend->restoreMachineState(p.machineState);  // throws, changing nothing, for another machine's
  s.radiosity = std::move(p.radiosity);
  s.unshotRadiosity = std::move(p.unshotRadiosity);
  s.unshotPowerW = std::move(p.unshotPowerW);
  s.timesShot = std::move(p.timesShot);
  s.ledger = p.ledger;
  s.history = std::move(p.history);
  s.firstShotPowerW = p.firstShotPowerW;
  s.convergence = p.convergence;
  s.exhausted = p.exhausted;
  s.elementRadiosity = std::move(p.elementRadiosity);
  s.cache = FormFactorCache(s.options.formFactorCacheBytes);
  for (auto row = p.cachedRows.rbegin(); row != p.cachedRows.rend(); ++row) s.cache.insert(*row);
}

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
