// A solve's progress taken out and put back (checkpoints: solver/radiosity/checkpoint.h), checked
// against the solve it is put into.
#include <algorithm>
#include <cmath>
#include <utility>
#include <fmt/format.h>
#include <optional>
#include <stdexcept>

#include "solver/radiosity/adaptive_split.h"
#include "solver/radiosity/progressive_solver.h"
#include "solver/radiosity/progressive_solver_state.h"

namespace radmesh {

namespace {

// Whether a progress has n patches and `elements` elements (0: patches receive) and names no
// others (a row's shooter and receivers, a record's shooters).
bool fitsPatches(const SolverProgress& p, size_t n, size_t elements) {
  auto patchIndex = [n](int j) { return j >= 0 && static_cast<size_t>(j) < n; };
  const size_t receivers = elements > 0 ? elements : n;
  auto receiverIndex = [receivers](int j) { return j >= 0 && static_cast<size_t>(j) < receivers; };
  auto rowFits = [&](const FormFactorRow& row) {
    auto shareFits = [&](const FormFactorRow::BinShare& b) {
      return receiverIndex(b.patch) && b.bin >= 0 && static_cast<size_t>(b.bin) < row.binTotals.size();
    };
    return patchIndex(row.shooter) && row.receivers.size() == row.formFactors.size() &&
           std::all_of(row.receivers.begin(), row.receivers.end(), receiverIndex) &&
           row.binBackFaces.size() == row.binTotals.size() &&
           std::all_of(row.binShares.begin(), row.binShares.end(), shareFits);
  };
  auto recordFits = [&](const IterationRecord& r) { return std::all_of(r.shooters.begin(), r.shooters.end(), patchIndex); };
  return p.radiosity.size() == n && p.unshotRadiosity.size() == n && p.unshotPowerW.size() == n &&
         p.elementRadiosity.size() == elements &&
         p.timesShot.size() == n && std::all_of(p.cachedRows.begin(), p.cachedRows.end(), rowFits) &&
         std::all_of(p.history.begin(), p.history.end(), recordFits);
}

bool physical(double v) { return std::isfinite(v) && v >= 0.0; }
bool physical(const Rgb& v) { return physical(v.r) && physical(v.g) && physical(v.b); }

// Throws std::invalid_argument naming the first of a progress's figures no solve makes: a power or
// radiosity that is negative or not finite, a negative shot count, a ledger that does not balance
// (a checkpoint whose checksum was mended after an edit).
void checkFigures(const SolverProgress& p) {
  auto all = [](const auto& values) { return std::all_of(values.begin(), values.end(), [](const auto& v) { return physical(v); }); };
  auto allBins = [&](const std::vector<std::vector<Rgb>>& bins) { return std::all_of(bins.begin(), bins.end(), all); };
  const std::pair<const char*, bool> figures[] = {
      {"radiosity", all(p.radiosity) && all(p.elementRadiosity)},
      {"unshot radiosity", all(p.unshotRadiosity)},
      {"unshot power", all(p.unshotPowerW) && physical(p.firstShotPowerW)},
      {"shot totals", all(p.shotTotal)},
      {"portal power", allBins(p.portalPower) && allBins(p.portalUnshot)},
      {"shot counts", std::all_of(p.timesShot.begin(), p.timesShot.end(), [](int t) { return t >= 0; })},
      {"convergence", std::isfinite(p.convergence) && p.convergence <= 1.0},  // 1 - s_i / s_1: below 0 early on
  };
  for (const auto& [name, ok] : figures)
    if (!ok) throw std::invalid_argument(fmt::format("its {} holds a value no solve makes", name));
  const Ledger& l = p.ledger;
  for (double Ledger::*term : Ledger::kTerms)
    if (!physical(l.*term)) throw std::invalid_argument(fmt::format("its energy ledger holds {} W", l.*term));
  if (!(l.imbalance() <= kLedgerTolerance))
    throw std::invalid_argument(fmt::format("its energy ledger does not balance (imbalance {:.3g} of the power)",
                                            l.imbalance()));
}

}  // namespace

SolverProgress ProgressiveSolver::progress() const {
  const State& s = *state_;
  return {s.radiosity, s.unshotRadiosity, s.unshotPowerW, s.timesShot, s.ledger, s.history,
          s.firstShotPowerW, s.convergence, s.exhausted, s.backend->machineState(), s.cache.contents(),
          s.elementRadiosity, s.adaptive() ? s.elements.level : std::vector<int>(), s.shotTotal,
          s.portalPower, s.portalUnshot};
}

void ProgressiveSolver::restoreProgress(SolverProgress p) {
  State& s = *state_;
  const size_t n = s.patches.size();
  // Adaptive: the elements split so far, from their levels (their geometry follows from them).
  std::optional<Elements> split;
  if (s.adaptive()) split = splitToLevels(s.patches, p.elementLevels);  // throws std::invalid_argument
  else if (!p.elementLevels.empty()) throw std::invalid_argument("element levels of an adaptive solve");
  auto binsFit = [&](const std::vector<std::vector<Rgb>>& saved, const std::vector<std::vector<Rgb>>& now) {
    return saved.size() == now.size() && std::equal(saved.begin(), saved.end(), now.begin(), [](const auto& a, const auto& b) {
             return a.size() == b.size();
           });
  };
  const size_t elements = split ? split->elements.size() : s.elementRadiosity.size();
  if (!fitsPatches(p, n, elements) || p.machineState.empty() != s.backend->machineState().empty() ||
      p.shotTotal.size() != s.shotTotal.size() || !binsFit(p.portalPower, s.portalPower) ||
      !binsFit(p.portalUnshot, s.portalUnshot))
    throw std::invalid_argument(fmt::format(
        "solver progress of another solve: not {} patches, shooters of other patches, other portal patches, or "
        "another back end", n));
  checkFigures(p);
  if (split) {  // as refine() leaves them after a split
    s.backend.reset();
    s.elements = std::move(*split);
    s.backend = s.makeBackend();  // with the portal patches' direction bins
    s.findNearField();
    s.adjacency = elementAdjacency(s.elements);
  }
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
  s.shotTotal = std::move(p.shotTotal);
  s.portalPower = std::move(p.portalPower);
  s.portalUnshot = std::move(p.portalUnshot);
  // Iteration 1 shot the scene's lights; a cells solve's came before it (splitAfterLights).
  s.lightsShot = s.buildingLightRow || (!s.history.empty() && !s.scene.lights.empty());
  s.cache = FormFactorCache(s.options.formFactorCacheBytes);
  for (auto row = p.cachedRows.rbegin(); row != p.cachedRows.rend(); ++row) s.cache.insert(*row);
}

}  // namespace radmesh
