// ProgressiveSolver's portal patches, for a cells solve (docs/cells.md): what reaches them waits by
// the bins of its direction of travel, and a portal patch shoots each bin into that bin's directions.
#include <array>
#include <fmt/format.h>
#include <span>
#include <stdexcept>
#include <utility>

#include "solver/formfactors/direction_bins.h"
#include "solver/radiosity/progressive_solver_state.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

using solver_state::channelSum;

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
      if (!portalReceiver(lit.receivers[r])) ledger.absorbed += channelSum(incident[r]);
  } else {
    receive<Rgb>(lit, incidentOf);
  }
  if (channelSum(uncovered) > 0.0) deliver(row, uncovered);
}

// How what reaches a portal patch (or one of its elements) from a shooter splits over the bins of its direction of travel,
// in the frame of the portal's back (the twin patch facing into the neighbour cell: u, -v, -n),
// where the light goes on: the directions from the shooter's centre through the patch, each bin's
// part weighted by its cosine to the portal's normal (which for a patch small against its distance
// is the shooter's cosine up to a constant), the shares adding up to 1.
void ProgressiveSolver::State::arrivalShares(int shooter, const Patch& p, std::vector<double>& shares) const {
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

void ProgressiveSolver::setPortalPatches(const std::vector<int>& portalPatches, int binsN) {
  State& s = *state_;
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

}  // namespace radmesh
