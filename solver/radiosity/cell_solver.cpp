#include "solver/radiosity/cell_solver.h"

#include <algorithm>
#include <array>
#include <deque>
#include <fmt/format.h>

#include "solver/formfactors/direction_bins.h"
#include "solver/formfactors/light_rows.h"
#include "solver/meshing/meshing.h"
#include "solver/projection/projection.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

namespace {

double channelSum(const Rgb& c) { return c.r + c.g + c.b; }

// Power reaching `patch` of `cell` moves, at the next exchange, to `twinPatch` of `twinCell`.
struct PortalLink {
  int cell = 0;
  int patch = 0;
  int twinCell = 0;
  int twinPatch = 0;
};

struct CellState {
  std::string name;
  std::vector<int> buildingPatch;  // per own patch (the first of the cell solve's): the building's index
  int portalPatches = 0;           // after the own ones
  std::unique_ptr<ProgressiveSolver> solver;  // none where another process solves the cell
};

// One light's shot over the whole building (CellSolver::State::shootLights), cut by cell.
struct LightShot {
  Rgb power;
  FormFactorRow row;
  std::vector<FormFactorRow> perCell;
};

// A cell's figures as the schedule and the building's ledger read them, in doubles for CellRanks:
// its ledger, iterations, whether it is exhausted, then what waits on each of its links.
constexpr size_t kFigures = 11;

std::vector<double> packFigures(const ProgressiveSolver& solver, std::vector<double> waitingW) {
  const Ledger& l = solver.ledger();
  std::vector<double> out{l.emitted, l.absorbed, l.unshot, l.notCaptured, l.escaped, l.absorbedByBackFaces,
                          l.portalOut, l.portalIn, l.lightOutside, static_cast<double>(solver.history().size()),
                          solver.exhausted() ? 1.0 : 0.0};
  out.insert(out.end(), waitingW.begin(), waitingW.end());
  return out;
}

Vec3 centre(const Cell& cell) { return 0.5 * (cell.boundsMin + cell.boundsMax); }

// The same patch seen from its other side.
Patch turned(const Patch& p) {
  Patch r = p;
  for (int k = 0; k < p.vertexCount; ++k) r.vertices[k] = p.vertices[p.vertexCount - 1 - k];
  r.normal = -p.normal;
  r.frame = Frame{p.frame.u, -p.frame.v, -p.frame.n};
  return r;
}

// The load of each cell: its patches (own and portal, what a shot projects) times 1 + cells x its
// share of the light it starts with (its emitters and what the lights sent it), the rounds' budget
// being shared by unshot power.
std::vector<double> cellLoads(const std::vector<int>& patchCount, const std::vector<double>& lightW) {
  double total = 0.0;
  for (double w : lightW) total += w;
  std::vector<double> load(patchCount.size());
  for (size_t c = 0; c < load.size(); ++c)
    load[c] = patchCount[c] * (1.0 + (total > 0.0 ? lightW[c] * static_cast<double>(load.size()) / total : 0.0));
  return load;
}

void validatePartition(const Scene& scene, size_t patchCount, const CellPartition& partition) {
  const int cells = static_cast<int>(partition.cells.size());
  if (partition.cellOfPatch.size() != patchCount)
    throw SceneError(scene.source, "the cell partition",
                     fmt::format("gives cells for {} patches, not the {} of the meshed scene",
                                 partition.cellOfPatch.size(), patchCount),
                     "find the cells of the same meshed scene");
  for (size_t j = 0; j < patchCount; ++j)
    if (partition.cellOfPatch[j] < kOutsideCell || partition.cellOfPatch[j] >= cells)
      throw SceneError(scene.source, fmt::format("patch {}", j),
                       fmt::format("is in cell {}, which does not exist", partition.cellOfPatch[j]),
                       "give every patch a cell of the partition, or kOutsideCell");
  for (size_t p = 0; p < partition.portals.size(); ++p) {
    const Portal& portal = partition.portals[p];
    const std::string element = fmt::format("portal {}", p);
    if (portal.cellA < 0 || portal.cellA >= cells || portal.cellB < 0 || portal.cellB >= cells ||
        portal.cellA == portal.cellB)
      throw SceneError(scene.source, element,
                       fmt::format("joins cells {} and {}", portal.cellA, portal.cellB),
                       "join two different cells of the partition");
    if (portal.vertices.size() < 3 || !(polygonArea(portal.vertices) > 0.0))
      throw SceneError(scene.source, element, "is not a polygon with an area",
                       "give it at least three vertices spanning the opening");
  }
}

}  // namespace

struct CellSolver::State {
  std::vector<Patch> patches;
  SolveOptions options;
  CellSolveSettings settings;
  std::vector<CellState> cells;
  std::vector<PortalLink> links;  // by cell, then patch: the exchange order
  std::vector<size_t> firstLink;  // per cell, and one past the last: where its links start
  std::vector<std::vector<int>> neighbours;
  int portalCount = 0;
  int focus = -1;
  std::vector<int> distance;  // from the focus, -1 where no portal leads
  int rounds = 0;
  // The lights' shots (State::shootLights) less what they handed to the cells: escaped, the backs
  // of one-sided patches. Part of the building's ledger, in no cell's.
  Ledger lights;
  ThreadPool pool;
  CellRanks* ranks;
  std::vector<int> owner;  // per cell: the process solving it
  // Every cell's figures as of the last refresh(), the same on every process: what the schedule,
  // done() and the building's ledger read.
  std::vector<Ledger> cellLedger;
  std::vector<int> cellIterations;
  std::vector<char> cellExhausted;
  std::vector<double> waitingW;  // per link: what waits on its portal patch, W

  State(std::vector<Patch> p, const SolveOptions& o, const CellSolveSettings& s, CellRanks* r)
      : patches(std::move(p)), options(o), settings(s), pool(o.threads), ranks(r) {}

  bool owns(int cell) const { return owner[cell] == (ranks ? ranks->rank() : 0); }

  // Portals from the focus, 30 where none leads (a cell's weight halves with each).
  int hops(int cell) const { return distance[cell] < 0 ? 30 : std::min(distance[cell], 30); }
  std::vector<int> shotsThisRound(const Ledger& building) const;
  void exchange();
  std::vector<LightShot> shootLights(const Scene& scene, const std::vector<int>& cellOf,
                                     const std::vector<int>& localOf);
  void receiveLights(const std::vector<LightShot>& shots);
  void refresh();
  template <typename PerCell>
  std::vector<Rgb> gatherPatches(PerCell perCell) const;
};

void checkPortalBins(int portalBins) {
  if (portalBins < 0 || portalBins > kMaxPortalBins)
    throw OptionError(fmt::format("--portal-bins {} is out of range: give 0 or 1 (diffuse) up to {} (an N x N "
                                  "hemicube of direction bins)", portalBins, kMaxPortalBins));
}

CellSolver::CellSolver(const Scene& scene, std::vector<Patch> patches, const CellPartition& partition,
                       const SolveOptions& options, const CellSolveSettings& settings, CellRanks* ranks)
    : state_(std::make_unique<State>(std::move(patches), options, settings, ranks)) {
  validateOptions(options);
  if (options.until < 1.0)
    throw OptionError("--cells auto stops on the unshot power of the whole building alone: give --until 1 with "
                      "--until-unshot (the bake preset does), not a convergence C");
  if (settings.exchangeShots < 1) throw OptionError("--exchange-shots must be at least 1");
  checkPortalBins(settings.portalBins);
  State& s = *state_;
  validatePartition(scene, s.patches.size(), partition);
  s.portalCount = static_cast<int>(partition.portals.size());

  // The cells' own patches, the outside (patches facing no cell) last, as a cell of its own.
  const int partitionCells = static_cast<int>(partition.cells.size());
  std::vector<std::vector<int>> own(partitionCells + 1);
  for (size_t j = 0; j < s.patches.size(); ++j) {
    const int c = partition.cellOfPatch[j];
    own[c == kOutsideCell ? partitionCells : c].push_back(static_cast<int>(j));
  }
  const int cellCount = own.back().empty() ? partitionCells : partitionCells + 1;
  s.neighbours.resize(cellCount);
  s.cells.resize(cellCount);
  std::vector<int> cellOf(s.patches.size()), localOf(s.patches.size());
  for (int c = 0; c < cellCount; ++c)
    for (size_t k = 0; k < own[c].size(); ++k) cellOf[own[c][k]] = c, localOf[own[c][k]] = static_cast<int>(k);
  const std::vector<LightShot> lightShots = s.shootLights(scene, cellOf, localOf);
  std::vector<int> patchCount(cellCount);
  std::vector<double> lightW(cellCount, 0.0);
  for (int c = 0; c < cellCount; ++c) {
    patchCount[c] = static_cast<int>(own[c].size());
    for (int j : own[c]) lightW[c] += channelSum(scene.materials[s.patches[j].material].emittance) * s.patches[j].areaM2;
  }
  for (const LightShot& shot : lightShots)
    for (int c = 0; c < cellCount; ++c) lightW[c] += channelSum(shot.power) * shot.perCell[c].hitFraction();

  // Every portal meshed once like a wall; the cell on each side gets the patches turned to face it.
  const Material portalMaterial{"portal", Rgb(0.0), Rgb(0.0)};
  std::vector<std::vector<Patch>> portalMesh(partition.portals.size());
  std::vector<bool> meshFacesB(partition.portals.size());
  for (size_t p = 0; p < partition.portals.size(); ++p) {
    const Portal& portal = partition.portals[p];
    Scene opening{scene.source, {portalMaterial}, {{portal.vertices, 0, fmt::format("portal {}", p)}}, {}, scene.upAxis};
    portalMesh[p] = meshScene(opening, settings.cellM);
    const Vec3 aToB = centre(partition.cells[portal.cellB]) - centre(partition.cells[portal.cellA]);
    meshFacesB[p] = glm::dot(newellNormal(portal.vertices), aToB) > 0.0;
    s.neighbours[portal.cellA].push_back(portal.cellB);
    s.neighbours[portal.cellB].push_back(portal.cellA);
    patchCount[portal.cellA] += static_cast<int>(portalMesh[p].size());
    patchCount[portal.cellB] += static_cast<int>(portalMesh[p].size());
  }
  s.owner = assignCellsToRanks(cellLoads(patchCount, lightW), ranks ? ranks->size() : 1);

  // Per cell: a scene of the polygons its patches came from (in the building's order) and its
  // portals, the building's materials and a black "portal" one (the solver passes portal light on).
  std::vector<std::array<int, 2>> portalFirstPatch(partition.portals.size(), {-1, -1});  // per side: A, B
  SolveOptions cellOptions = options;
  cellOptions.threads = 1;  // the cells run in parallel, each on one thread
  for (int c = 0; c < cellCount; ++c) {
    CellState& cell = s.cells[c];
    cell.name = c < partitionCells ? partition.cells[c].name : "outside";
    cell.buildingPatch = own[c];
    Scene sub{scene.source, scene.materials, {}, {}, scene.upAxis};
    sub.materials.push_back(portalMaterial);
    const int portalMaterialIndex = static_cast<int>(sub.materials.size()) - 1;
    std::vector<char> used(scene.polygons.size(), 0);
    for (int j : own[c]) used[s.patches[j].polygon] = 1;
    std::vector<int> polygonIndex(scene.polygons.size(), -1);
    for (size_t i = 0; i < scene.polygons.size(); ++i)
      if (used[i]) polygonIndex[i] = static_cast<int>(sub.polygons.size()), sub.polygons.push_back(scene.polygons[i]);
    std::vector<Patch> local;
    for (int j : own[c]) {
      local.push_back(s.patches[j]);
      local.back().polygon = polygonIndex[s.patches[j].polygon];
    }
    std::vector<int> portalPatches;
    for (size_t p = 0; p < partition.portals.size(); ++p) {
      const Portal& portal = partition.portals[p];
      const int side = portal.cellA == c ? 0 : portal.cellB == c ? 1 : -1;
      if (side < 0) continue;
      const bool turn = (side == 1) != meshFacesB[p];
      Polygon opening{portal.vertices, portalMaterialIndex, fmt::format("portal {}", p)};
      if (turn) std::reverse(opening.vertices.begin(), opening.vertices.end());
      portalFirstPatch[p][side] = static_cast<int>(local.size());
      for (const Patch& patch : portalMesh[p]) {
        portalPatches.push_back(static_cast<int>(local.size()));
        local.push_back(turn ? turned(patch) : patch);
        local.back().material = portalMaterialIndex;
        local.back().polygon = static_cast<int>(sub.polygons.size());
      }
      sub.polygons.push_back(std::move(opening));
    }
    cell.portalPatches = static_cast<int>(portalPatches.size());
    if (!s.owns(c)) continue;
    cell.solver = std::make_unique<ProgressiveSolver>(sub, std::move(local), cellOptions);
    cell.solver->setPortalPatches(portalPatches, settings.portalBins);
  }

  for (size_t p = 0; p < partition.portals.size(); ++p) {
    const Portal& portal = partition.portals[p];
    for (int k = 0; k < static_cast<int>(portalMesh[p].size()); ++k) {
      const int a = portalFirstPatch[p][0] + k, b = portalFirstPatch[p][1] + k;
      s.links.push_back({portal.cellA, a, portal.cellB, b});
      s.links.push_back({portal.cellB, b, portal.cellA, a});
    }
  }
  std::sort(s.links.begin(), s.links.end(), [](const PortalLink& x, const PortalLink& y) {
    return x.cell != y.cell ? x.cell < y.cell : x.patch < y.patch;
  });
  s.firstLink.assign(cellCount + 1, 0);
  for (const PortalLink& link : s.links) ++s.firstLink[link.cell + 1];
  for (int c = 0; c < cellCount; ++c) s.firstLink[c + 1] += s.firstLink[c];
  s.receiveLights(lightShots);
  s.refresh();
  focus(-1);
}

std::vector<int> assignCellsToRanks(const std::vector<double>& load, int ranks) {
  double total = 0.0;
  for (double l : load) total += l;
  std::vector<int> owner(load.size(), 0);
  double before = 0.0;
  for (size_t c = 0; c < load.size(); ++c) {
    const double midpoint = total > 0.0 ? (before + 0.5 * load[c]) / total : (c + 0.5) / load.size();
    owner[c] = std::min(ranks - 1, static_cast<int>(midpoint * ranks));
    before += load[c];
  }
  return owner;
}

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
// cell holding more than its share (1/cells) of the stopping threshold shoots at least once, and
// so does the strongest: the round that shoots nothing is the one after done(). Until the focus
// cell itself is below the stopping rule, cells more than one portal from it wait (no share, no
// minimum): a hundred rooms shooting once a round each would cost the camera's room most of it.
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
  const double thresholdW = options.untilUnshot * (building.input() - building.lightOutside) / n;
  const int strongest = static_cast<int>(std::max_element(weight.begin(), weight.end()) - weight.begin());
  std::vector<int> shots(n, 0);
  for (int c = 0; c < n; ++c) {
    if (total > 0.0) shots[c] = static_cast<int>(std::min(budget * (weight[c] / total), 1e9));  // no int overflow
    if ((!waits(c) && cellLedger[c].unshot > thresholdW) || c == strongest) shots[c] = std::max(shots[c], 1);
  }
  return shots;
}

// Each light's one shot over the whole building's patches (solver/formfactors/light_rows.h), as
// the whole solve shoots it in its first iteration, cut by cell (receiveLights hands it on).
std::vector<LightShot> CellSolver::State::shootLights(const Scene& scene, const std::vector<int>& cellOf,
                                                      const std::vector<int>& localOf) {
  std::vector<LightShot> shots;
  if (scene.lights.empty()) return shots;
  const double nearDepth = sceneNearDepth(patches);
  for (const Light& light : scene.lights) {
    LightShot& shot = shots.emplace_back();
    shot.power = lightPower(scene, light);
    shot.perCell.resize(cells.size());
    if (!(channelSum(shot.power) > 0.0)) continue;  // a dark light, or a beam with no window
    shot.row = lightRow(scene, light, patches, options.resolution, nearDepth, pool);
    for (size_t r = 0; r < shot.row.receivers.size(); ++r) {  // ascending in the building, so in each cell
      FormFactorRow& part = shot.perCell[cellOf[shot.row.receivers[r]]];
      part.receivers.push_back(localOf[shot.row.receivers[r]]);
      part.formFactors.push_back(shot.row.formFactors[r]);
    }
  }
  return shots;
}

// What lands on a cell's patches the cell receives as emitted power (ProgressiveSolver::
// receiveLight); what escapes or lands on the back of a one-sided patch is booked here, in the
// building's ledger.
void CellSolver::State::receiveLights(const std::vector<LightShot>& shots) {
  for (const LightShot& shot : shots) {
    const double powerW = channelSum(shot.power);
    lights.emitted += powerW;
    if (!(powerW > 0.0)) continue;
    for (size_t c = 0; c < cells.size(); ++c) {
      const FormFactorRow& part = shot.perCell[c];
      if (part.receivers.empty()) continue;
      if (owns(static_cast<int>(c))) cells[c].solver->receiveLight(part, shot.power);
      lights.emitted -= powerW * part.hitFraction();  // what the cell received
    }
    lights.notCaptured += powerW * (1.0 - shot.row.capturedFraction);
    lights.escaped += powerW * shot.row.escapedFraction();
    lights.absorbed += powerW * shot.row.backFaces;
    lights.absorbedByBackFaces += powerW * shot.row.backFaces;
    lights.lightOutside += powerW * (shot.row.escapedFraction() + shot.row.backFaces);
  }
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
    figures[c] = packFigures(*cells[c].solver, std::move(waiting));
  }
  if (ranks) ranks->shareCells(owner, figures);
  cellLedger.resize(n);
  cellIterations.resize(n);
  cellExhausted.resize(n);
  waitingW.resize(links.size());
  for (int c = 0; c < n; ++c) {
    const std::vector<double>& f = figures[c];
    cellLedger[c] = Ledger{f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7], f[8]};
    cellIterations[c] = static_cast<int>(f[9]);
    cellExhausted[c] = f[10] != 0.0;
    std::copy(f.begin() + kFigures, f.end(), waitingW.begin() + static_cast<std::ptrdiff_t>(firstLink[c]));
  }
}

// In link order (by cell, then patch), on every process: a link whose cells are both this
// process's moves its power directly; one from another process's cell takes its power from that
// process's message, which holds its links to this process's cells in the same order. A cell
// receives in the same order as without ranks, so its sums are the same bit for bit.
void CellSolver::State::exchange() {
  const size_t bins = static_cast<size_t>(directionBinCount(settings.portalBins));
  const int processes = ranks ? ranks->size() : 1;
  std::vector<std::vector<double>> outgoing(processes);
  std::vector<size_t> incomingSizes(processes, 0);
  for (const PortalLink& link : links) {
    if (owns(link.cell) && !owns(link.twinCell))
      for (const Rgb& bin : cells[link.cell].solver->takePortalPower(link.patch))
        outgoing[owner[link.twinCell]].insert(outgoing[owner[link.twinCell]].end(), {bin.r, bin.g, bin.b});
    if (!owns(link.cell) && owns(link.twinCell)) incomingSizes[owner[link.cell]] += 3 * bins;
  }
  std::vector<std::vector<double>> incoming(processes);
  if (ranks) incoming = ranks->exchange(outgoing, incomingSizes);
  std::vector<size_t> read(processes, 0);
  for (const PortalLink& link : links) {
    if (!owns(link.twinCell)) continue;
    std::vector<Rgb> power;
    if (owns(link.cell)) {
      power = cells[link.cell].solver->takePortalPower(link.patch);
    } else {
      const std::vector<double>& message = incoming[owner[link.cell]];
      size_t& at = read[owner[link.cell]];
      for (size_t b = 0; b < bins; ++b, at += 3) power.emplace_back(message[at], message[at + 1], message[at + 2]);
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
  s.pool.parallelFor(static_cast<int>(active.size()), [&](int i, int) {
    ProgressiveSolver& solver = *s.cells[active[i]].solver;
    for (int n = 0; n < shots[active[i]] && !solver.exhausted(); ++n) solver.step();
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
  return exhausted() || (o.untilUnshot > 0.0 && ledger().unshotFraction() <= o.untilUnshot) ||
         iterations() >= o.maxIterations;
}

void CellSolver::setUntilUnshot(double untilUnshot) {
  SolveOptions changed = state_->options;
  changed.untilUnshot = untilUnshot;
  validateOptions(changed);
  state_->options = changed;
}

Ledger CellSolver::ledger() const {
  const State& s = *state_;
  Ledger total;
  std::vector<const Ledger*> parts{&s.lights};
  for (const Ledger& cell : s.cellLedger) parts.push_back(&cell);
  for (const Ledger* part : parts) {
    const Ledger& l = *part;
    total.emitted += l.emitted;
    total.absorbed += l.absorbed;
    total.unshot += l.unshot;
    total.notCaptured += l.notCaptured;
    total.escaped += l.escaped;
    total.absorbedByBackFaces += l.absorbedByBackFaces;
    total.lightOutside += l.lightOutside;
  }
  for (double w : s.waitingW) total.unshot += w;
  return total;
}

int CellSolver::iterations() const {
  int n = 0;
  for (int cellIterations : state_->cellIterations) n += cellIterations;
  return n;
}

int CellSolver::rounds() const { return state_->rounds; }

// Per building patch, what `perCell` gives for each cell's own patches, from every process.
template <typename PerCell>
std::vector<Rgb> CellSolver::State::gatherPatches(PerCell perCell) const {
  std::vector<std::vector<double>> values(cells.size());
  for (size_t c = 0; c < cells.size(); ++c) {
    if (!owns(static_cast<int>(c))) {
      values[c].resize(3 * cells[c].buildingPatch.size());
      continue;
    }
    const std::vector<Rgb>& b = perCell(*cells[c].solver);
    for (size_t j = 0; j < cells[c].buildingPatch.size(); ++j) values[c].insert(values[c].end(), {b[j].r, b[j].g, b[j].b});
  }
  if (ranks) ranks->shareCells(owner, values);
  std::vector<Rgb> out(patches.size(), Rgb(0.0));
  for (size_t c = 0; c < cells.size(); ++c)
    for (size_t j = 0; j < cells[c].buildingPatch.size(); ++j)
      out[cells[c].buildingPatch[j]] = Rgb(values[c][3 * j], values[c][3 * j + 1], values[c][3 * j + 2]);
  return out;
}

std::vector<Rgb> CellSolver::radiosity() const {
  return state_->gatherPatches([](const ProgressiveSolver& s) { return s.radiosity(); });
}

std::vector<Rgb> CellSolver::displayRadiosity() const {
  return state_->gatherPatches([](const ProgressiveSolver& s) { return s.displayRadiosity(); });
}

const std::vector<Patch>& CellSolver::patches() const { return state_->patches; }
int CellSolver::cellCount() const { return static_cast<int>(state_->cells.size()); }
int CellSolver::portalCount() const { return state_->portalCount; }
int CellSolver::owner(int cell) const { return state_->owner.at(static_cast<size_t>(cell)); }

const ProgressiveSolver& CellSolver::cellSolver(int cell) const {
  const ProgressiveSolver* solver = state_->cells.at(static_cast<size_t>(cell)).solver.get();
  if (!solver) throw std::out_of_range(fmt::format("cell {} is solved by process {}", cell, owner(cell)));
  return *solver;
}
const SolveOptions& CellSolver::options() const { return state_->options; }
const CellSolveSettings& CellSolver::settings() const { return state_->settings; }

std::vector<CellFigures> CellSolver::cellFigures() const {
  const State& s = *state_;
  std::vector<CellFigures> figures;
  for (size_t c = 0; c < s.cells.size(); ++c)
    figures.push_back({s.cells[c].name, static_cast<int>(s.cells[c].buildingPatch.size()), s.cells[c].portalPatches,
                       s.cellIterations[c], s.cellLedger[c], 0.0});
  for (size_t k = 0; k < s.links.size(); ++k) figures[s.links[k].cell].waitingW += s.waitingW[k];
  return figures;
}

}  // namespace radmesh
