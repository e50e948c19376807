// The cells solve's rounds: the schedule, every cell's figures, the portal exchange, and the
// building's figures read from the cells (made in cell_solver_setup.cpp; its radiosity and
// elements gathered in cell_solver_gather.cpp).
#include "solver/radiosity/cell_solver.h"

#include <algorithm>
#include <cstring>
#include <deque>
#include <fmt/format.h>
#include <stdexcept>

#include "solver/formfactors/direction_bins.h"
#include "solver/radiosity/cell_solver_state.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

void requireCellsOptions(const SolveOptions& options) {
  if (options.backend != Backend::Native)
    throw OptionError("--cells auto runs on the native back end only: each cell's solver would keep its own "
                      "emulated MP-1 (its PE memory, item buffers and patch state), a machine per cell, too much "
                      "memory for a building of a hundred rooms; give --backend native, or --cells off");
}

using namespace cell_state;

CellSolver::~CellSolver() = default;

void CellSolver::focus(int cell) {
  State& s = *state_;
  const int n = static_cast<int>(s.cells.size());
  s.focus = cell >= 0 && cell < n ? cell : -1;
  s.distance.assign(n, s.focus < 0 ? 0 : -1);
  if (s.focus >= 0) {  // breadth first over the portals
    std::deque<int> queue{s.focus};
    s.distance[s.focus] = 0;
    for (; !queue.empty(); queue.pop_front())
      for (int next : s.neighbours[queue.front()])
        if (s.distance[next] < 0) s.distance[next] = s.distance[queue.front()] + 1, queue.push_back(next);
  }
}

int CellSolver::portalDistance(int cell) const { return state_->distance.at(static_cast<size_t>(cell)); }

// The round's budget, exchangeShots a cell (with a focus, halved at each portal of distance from
// it, so that a round stays short), shared in proportion to each cell's unshot power (halved the
// same way), so that the cells shoot roughly in the order the whole building's solve would. A
// cell holding more than its share (1/cells) of the stopping threshold, or an emitting patch yet
// to shoot (a dim room's lamp), shoots at least once, and so does the strongest: the round that
// shoots nothing is the one after done(). Until the focus cell itself is below the stopping rule,
// cells more than one portal from it wait (no share, no minimum): a hundred rooms shooting once a
// round each would cost the camera's room most of it.
std::vector<int> CellSolver::State::shotsThisRound(const Ledger& building) const {
  const int n = static_cast<int>(cells.size());
  std::vector<double> weight(n);
  double total = 0.0, budget = 0.0;
  const bool focusFirst = focus >= 0 && cellLedger[focus].unshotFraction() > options.untilUnshot;
  auto waits = [&](int c) { return focusFirst && hops(c) > 0; };
  for (int c = 0; c < n; ++c) {
    if (waits(c)) continue;
    const int d = hops(c);
    weight[c] = std::ldexp(cellLedger[c].unshot, -d);
    total += weight[c];
    budget += std::ldexp(static_cast<double>(settings.exchangeShots), -d);
  }
  const double thresholdW = options.untilUnshot * building.cameIn() / n;
  const int strongest = static_cast<int>(std::max_element(weight.begin(), weight.end()) - weight.begin());
  std::vector<int> shots(n, 0);
  for (int c = 0; c < n; ++c) {
    if (total > 0.0) shots[c] = static_cast<int>(std::min(budget * (weight[c] / total), 1e9));  // no int overflow
    const bool due = cellLedger[c].unshot > thresholdW || (options.untilUnshot > 0.0 && cellEmittersToShoot[c] > 0);
    if ((!waits(c) && due) || c == strongest) shots[c] = std::max(shots[c], 1);
  }
  return shots;
}

// Every cell's figures: this process's from its solvers, the others' from their processes.
void CellSolver::State::refresh() {
  const int n = static_cast<int>(cells.size());
  std::vector<std::vector<double>> figures(n);
  for (int c = 0; c < n; ++c) {
    if (!owns(c)) {
      figures[c].resize(kFigures + firstLink[c + 1] - firstLink[c]);
      continue;
    }
    std::vector<double> waiting;
    for (size_t k = firstLink[c]; k < firstLink[c + 1]; ++k)
      waiting.push_back(channelSum(cells[c].solver->portalPower(links[k].patch)));
    figures[c] = packFigures(*cells[c].solver, static_cast<int>(cells[c].buildingPatch.size()), std::move(waiting));
  }
  if (ranks) ranks->shareCells(owner, figures);
  cellLedger.resize(n);
  cellIterations.resize(n);
  cellExhausted.resize(n);
  cellElements.resize(n);
  cellEmittersToShoot.resize(n);
  waitingW.resize(links.size());
  for (int c = 0; c < n; ++c) {
    const std::vector<double>& f = figures[c];
    const size_t terms = Ledger::kTerms.size();
    for (size_t t = 0; t < terms; ++t) cellLedger[c].*Ledger::kTerms[t] = f[t];
    cellIterations[c] = static_cast<int>(f[terms]);
    cellExhausted[c] = f[terms + 1] != 0.0;
    cellElements[c] = static_cast<int>(f[terms + 2]);
    cellEmittersToShoot[c] = static_cast<int>(f[terms + 3]);
    std::copy(f.begin() + kFigures, f.end(), waitingW.begin() + static_cast<std::ptrdiff_t>(firstLink[c]));
  }
}

// In link order (by cell, then patch), on every process: a link whose cells are both this
// process's moves its power directly; one from another process's cell takes its power from that
// process's message, which holds its links to this process's cells in the same order (portalMessage:
// the runs of lit bins, or the full bins where shorter). A cell receives in the same order as
// without ranks, so its sums are the same bit for bit. Every link records its runs' length, what
// it sends or would send were its cells on two processes (portalTraffic: docs/scaling.md's model).
void CellSolver::State::exchange() {
  const size_t bins = static_cast<size_t>(directionBinCount(settings.portalBins));
  const int processes = ranks ? ranks->size() : 1;
  std::vector<std::vector<double>> runs(processes), outgoing(processes);
  std::vector<std::vector<Rgb>> full(processes);
  std::vector<size_t> linksTo(processes, 0), linksFrom(processes, 0), incomingLimits(processes, 0);
  std::vector<int>& runDoubles = linkRunDoubles.emplace_back(links.size(), 0);
  for (size_t k = 0; k < links.size(); ++k) {
    const PortalLink& link = links[k];
    if (owns(link.cell) && !owns(link.twinCell)) {
      const int to = owner[link.twinCell];
      const std::vector<Rgb> power = cells[link.cell].solver->takePortalPower(link.patch);
      runDoubles[k] = static_cast<int>(appendPortalRuns(power, linksTo[to]++, runs[to]));
      full[to].insert(full[to].end(), power.begin(), power.end());
    }
    if (!owns(link.cell) && owns(link.twinCell)) ++linksFrom[owner[link.cell]], incomingLimits[owner[link.cell]] += 3 * bins;
  }
  for (int r = 0; r < processes; ++r) outgoing[r] = portalMessage(std::move(runs[r]), full[r]);
  std::vector<std::vector<double>> incoming(processes);
  if (ranks) incoming = ranks->exchange(outgoing, incomingLimits);
  std::vector<std::vector<Rgb>> received(processes);
  for (int r = 0; r < processes; ++r)
    if (linksFrom[r] > 0) received[r] = readPortalMessage(incoming[r], linksFrom[r], bins);
  std::vector<size_t> read(processes, 0);
  std::vector<double> unsent;
  for (size_t k = 0; k < links.size(); ++k) {
    const PortalLink& link = links[k];
    if (!owns(link.twinCell)) continue;
    std::vector<Rgb> power;
    if (owns(link.cell)) {
      power = cells[link.cell].solver->takePortalPower(link.patch);
      unsent.clear();
      runDoubles[k] = static_cast<int>(appendPortalRuns(power, 0, unsent));
    } else {
      const std::vector<Rgb>& message = received[owner[link.cell]];
      size_t& at = read[owner[link.cell]];
      power.assign(message.begin() + static_cast<std::ptrdiff_t>(at), message.begin() + static_cast<std::ptrdiff_t>(at + bins));
      at += bins;
    }
    cells[link.twinCell].solver->addPortalPower(link.twinPatch, power);
  }
}

void CellSolver::round() {
  State& s = *state_;
  const std::vector<int> shots = s.shotsThisRound(ledger());
  std::vector<int> active;
  for (int c = 0; c < cellCount(); ++c)
    if (shots[c] > 0 && s.owns(c) && !s.cells[c].solver->exhausted()) active.push_back(c);
  // Nearest the focus first; among cells as near, the longest first (shots times patches), so that
  // the threads finish the round together. Which thread runs a cell does not change its result.
  auto cost = [&](int c) { return static_cast<double>(shots[c]) * s.cells[c].solver->patches().size(); };
  std::stable_sort(active.begin(), active.end(), [&](int a, int b) {
    return s.hops(a) != s.hops(b) ? s.hops(a) < s.hops(b) : cost(a) > cost(b);
  });
  // A cell's item buffers and set-ups are freed after its turn: held by every cell of a building
  // between turns, they would be hundreds of megabytes (docs/cells.md).
  s.pool.parallelFor(static_cast<int>(active.size()), [&](int i, int) {
    ProgressiveSolver& solver = *s.cells[active[i]].solver;
    for (int n = 0; n < shots[active[i]] && !solver.exhausted(); ++n) solver.step();
    solver.releaseScratch();
  });
  ++s.rounds;
  s.refresh();
  checkLedger(ledger(), iterations());
  s.exchange();
  s.refresh();
  checkLedger(ledger(), iterations());
}

bool CellSolver::exhausted() const {
  const State& s = *state_;
  const bool waiting = std::any_of(s.waitingW.begin(), s.waitingW.end(), [](double w) { return w > 0.0; });
  return !waiting && std::all_of(s.cellExhausted.begin(), s.cellExhausted.end(), [](char e) { return e != 0; });
}

bool CellSolver::done() const {
  const SolveOptions& o = state_->options;
  // Less unshot than the ledger vouches for is nothing left: with no unshot stop (--until-unshot
  // 0), the rounds would otherwise go on shooting rounding until --max-iterations (C, which ends
  // a whole solve there, is not defined across cells).
  const double unshot = ledger().unshotFraction();
  const auto& waiting = state_->cellEmittersToShoot;
  const bool emittersShot = o.untilUnshot == 0.0 || std::all_of(waiting.begin(), waiting.end(), [](int e) { return e == 0; });
  return exhausted() || (unshot <= std::max(o.untilUnshot, kLedgerTolerance) && emittersShot) ||
         iterations() >= o.maxIterations;
}

void CellSolver::setUntilUnshot(double untilUnshot) {
  SolveOptions changed = state_->options;
  changed.untilUnshot = untilUnshot;
  validateOptions(changed);
  state_->options = changed;
}

void CellSolver::dropFormFactorCaches() {
  for (auto& cell : state_->cells)
    if (cell.solver) cell.solver->dropFormFactorCache();
}

Ledger CellSolver::ledger() const {
  const State& s = *state_;
  Ledger total;
  std::vector<const Ledger*> parts{&s.lights};
  for (const Ledger& cell : s.cellLedger) parts.push_back(&cell);
  for (const Ledger* part : parts) {
    for (double Ledger::*term : Ledger::kTerms) total.*term += part->*term;
  }
  // Within the building, portal light only moves between cells: what waits on a link is unshot.
  total.portalOut = total.portalIn = 0.0;
  for (double w : s.waitingW) total.unshot += w;
  return total;
}

int CellSolver::iterations() const {
  int n = 0;
  for (int cellIterations : state_->cellIterations) n += cellIterations;
  return n;
}

int CellSolver::rounds() const { return state_->rounds; }

const std::vector<Patch>& CellSolver::patches() const { return state_->patches; }
int CellSolver::cellCount() const { return static_cast<int>(state_->cells.size()); }
int CellSolver::portalCount() const { return state_->portalCount; }
int CellSolver::owner(int cell) const { return state_->owner.at(static_cast<size_t>(cell)); }

const ProgressiveSolver& CellSolver::cellSolver(int cell) const {
  const ProgressiveSolver* solver = state_->cells.at(static_cast<size_t>(cell)).solver.get();
  if (!solver) throw std::out_of_range(fmt::format("cell {} is solved by process {}", cell, owner(cell)));
  return *solver;
}
std::vector<PortalLinkTraffic> CellSolver::portalTraffic() const {
  const State& s = *state_;
  const size_t exchanges = s.linkRunDoubles.size();
  std::vector<std::vector<double>> perCell(s.cells.size());  // per link, per exchange
  for (size_t c = 0; c < s.cells.size(); ++c)
    for (size_t k = s.firstLink[c]; k < s.firstLink[c + 1]; ++k)
      for (const std::vector<int>& exchange : s.linkRunDoubles) perCell[c].push_back(exchange[k]);
  if (s.ranks) s.ranks->shareCells(s.owner, perCell);
  std::vector<PortalLinkTraffic> out;
  for (size_t c = 0; c < s.cells.size(); ++c)
    for (size_t k = s.firstLink[c]; k < s.firstLink[c + 1]; ++k) {
      const auto first = perCell[c].begin() + static_cast<std::ptrdiff_t>((k - s.firstLink[c]) * exchanges);
      out.push_back({s.links[k].cell, s.links[k].twinCell, std::vector<int>(first, first + static_cast<std::ptrdiff_t>(exchanges))});
    }
  return out;
}

std::size_t CellSolver::figureDoubles() const { return kFigures * state_->cells.size() + state_->links.size(); }

std::vector<double> CellSolver::cellLoads() const { return state_->load; }
const SolveOptions& CellSolver::options() const { return state_->options; }
const CellSolveSettings& CellSolver::settings() const { return state_->settings; }

bool CellSolver::solvesHere(int cell) const { return state_->owns(cell); }
bool CellSolver::writesHere() const { return !state_->ranks || state_->ranks->rank() == 0; }
const Ledger& CellSolver::lightsLedger() const { return state_->lights; }

std::vector<std::string> CellSolver::gatherOnFirst(std::vector<std::string> perCell) const {
  const State& s = *state_;
  if (!s.ranks) return perCell;
  // This process's cells in cell order, each as its length (8 bytes) and its bytes.
  std::string mine;
  for (size_t c = 0; c < perCell.size(); ++c) {
    if (!s.owns(static_cast<int>(c))) continue;
    const std::uint64_t size = perCell[c].size();
    mine.append(reinterpret_cast<const char*>(&size), sizeof size).append(perCell[c]);
  }
  const std::vector<std::string> byRank = s.ranks->gatherOnFirst(mine);
  if (!writesHere()) return perCell;
  std::vector<size_t> at(byRank.size(), 0);
  for (size_t c = 0; c < perCell.size(); ++c) {
    const std::string& from = byRank.at(static_cast<size_t>(s.owner[c]));
    size_t& next = at[s.owner[c]];
    std::uint64_t size = 0;
    if (from.size() - next < sizeof size) throw std::runtime_error(fmt::format("cell {}'s state did not arrive", c));
    std::memcpy(&size, from.data() + next, sizeof size);
    next += sizeof size;
    if (from.size() - next < size) throw std::runtime_error(fmt::format("cell {}'s state arrived cut short", c));
    perCell[c] = from.substr(next, size);
    next += size;
  }
  return perCell;
}

void CellSolver::restoreProgress(int rounds, const Ledger& lights,
                                 const std::function<void(int cell, ProgressiveSolver& solver)>& restoreCell) {
  State& s = *state_;
  for (int c = 0; c < cellCount(); ++c)
    if (s.owns(c)) restoreCell(c, *s.cells[c].solver);
  s.rounds = rounds;
  s.lights = lights;
  s.refresh();
}

std::vector<CellFigures> CellSolver::cellFigures() const {
  const State& s = *state_;
  std::vector<CellFigures> figures;
  for (size_t c = 0; c < s.cells.size(); ++c)
    figures.push_back({s.cells[c].name, static_cast<int>(s.cells[c].buildingPatch.size()), s.cellElements[c],
                       s.cells[c].portalPatches, s.cellIterations[c], s.cellLedger[c], 0.0});
  for (size_t k = 0; k < s.links.size(); ++k) figures[s.links[k].cell].waitingW += s.waitingW[k];
  return figures;
}

}  // namespace radmesh
