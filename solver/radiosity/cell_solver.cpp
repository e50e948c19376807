#include "solver/radiosity/cell_solver.h"

#include <algorithm>
#include <array>
#include <deque>
#include <fmt/format.h>

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
  std::unique_ptr<ProgressiveSolver> solver;
};

Vec3 centre(const Cell& cell) { return 0.5 * (cell.boundsMin + cell.boundsMax); }

// The same patch seen from its other side.
Patch turned(const Patch& p) {
  Patch r = p;
  for (int k = 0; k < p.vertexCount; ++k) r.vertices[k] = p.vertices[p.vertexCount - 1 - k];
  r.normal = -p.normal;
  r.frame = Frame{p.frame.u, -p.frame.v, -p.frame.n};
  return r;
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
  std::vector<std::vector<int>> neighbours;
  int portalCount = 0;
  int focus = -1;
  std::vector<int> distance;  // from the focus, -1 where no portal leads
  int rounds = 0;
  // The lights' shots (State::shootLights) less what they handed to the cells: escaped, the backs
  // of one-sided patches. Part of the building's ledger, in no cell's.
  Ledger lights;
  ThreadPool pool;

  State(std::vector<Patch> p, const SolveOptions& o, const CellSolveSettings& s)
      : patches(std::move(p)), options(o), settings(s), pool(o.threads) {}

  // Portals from the focus, 30 where none leads (a cell's weight halves with each).
  int hops(int cell) const { return distance[cell] < 0 ? 30 : std::min(distance[cell], 30); }
  std::vector<int> shotsThisRound(const Ledger& building) const;
  void exchange();
  void shootLights(const Scene& scene);
};

void checkPortalBins(int portalBins) {
  if (portalBins < 0 || portalBins > kMaxPortalBins)
    throw OptionError(fmt::format("--portal-bins {} is out of range: give 0 or 1 (diffuse) up to {} (an N x N "
                                  "hemicube of direction bins)", portalBins, kMaxPortalBins));
}

CellSolver::CellSolver(const Scene& scene, std::vector<Patch> patches, const CellPartition& partition,
                       const SolveOptions& options, const CellSolveSettings& settings)
    : state_(std::make_unique<State>(std::move(patches), options, settings)) {
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
  }

  // Per cell: a scene of the polygons its patches came from (in the building's order) and its
  // portals, the building's materials and a black "portal" one (the solver passes portal light on).
  std::vector<std::array<int, 2>> portalFirstPatch(partition.portals.size(), {-1, -1});  // per side: A, B
  SolveOptions cellOptions = options;
  cellOptions.threads = 1;  // the cells run in parallel, each on one thread
  s.cells.resize(cellCount);
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
  s.shootLights(scene);
  focus(-1);
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
  const bool focusFirst = focus >= 0 && cells[focus].solver->ledger().unshotFraction() > options.untilUnshot;
  auto waits = [&](int c) { return focusFirst && hops(c) > 0; };
  for (int c = 0; c < n; ++c) {
    if (waits(c)) continue;
    const int d = hops(c);
    weight[c] = std::ldexp(cells[c].solver->ledger().unshot, -d);
    total += weight[c];
    budget += std::ldexp(static_cast<double>(settings.exchangeShots), -d);
  }
  const double thresholdW = options.untilUnshot * (building.input() - building.lightOutside) / n;
  const int strongest = static_cast<int>(std::max_element(weight.begin(), weight.end()) - weight.begin());
  std::vector<int> shots(n, 0);
  for (int c = 0; c < n; ++c) {
    if (total > 0.0) shots[c] = static_cast<int>(std::min(budget * (weight[c] / total), 1e9));  // no int overflow
    if ((!waits(c) && cells[c].solver->ledger().unshot > thresholdW) || c == strongest) shots[c] = std::max(shots[c], 1);
  }
  return shots;
}

// Each light's one shot over the whole building's patches (solver/formfactors/light_rows.h), as
// the whole solve shoots it in its first iteration: what lands on a cell's patches the cell
// receives as emitted power (ProgressiveSolver::receiveLight); what escapes or lands on the back
// of a one-sided patch is booked here, in the building's ledger.
void CellSolver::State::shootLights(const Scene& scene) {
  if (scene.lights.empty()) return;
  std::vector<int> cellOf(patches.size()), localOf(patches.size());
  for (size_t c = 0; c < cells.size(); ++c)
    for (size_t k = 0; k < cells[c].buildingPatch.size(); ++k)
      cellOf[cells[c].buildingPatch[k]] = static_cast<int>(c), localOf[cells[c].buildingPatch[k]] = static_cast<int>(k);
  const double nearDepth = sceneNearDepth(patches);
  for (const Light& light : scene.lights) {
    const Rgb power = lightPower(scene, light);
    const double powerW = channelSum(power);
    lights.emitted += powerW;
    if (!(powerW > 0.0)) continue;  // a dark light, or a beam with no window
    const FormFactorRow row = lightRow(scene, light, patches, options.resolution, nearDepth, pool);
    std::vector<FormFactorRow> perCell(cells.size());
    for (size_t r = 0; r < row.receivers.size(); ++r) {  // ascending in the building, so in each cell
      FormFactorRow& part = perCell[cellOf[row.receivers[r]]];
      part.receivers.push_back(localOf[row.receivers[r]]);
      part.formFactors.push_back(row.formFactors[r]);
    }
    for (size_t c = 0; c < cells.size(); ++c)
      if (!perCell[c].receivers.empty()) lights.emitted -= cells[c].solver->receiveLight(perCell[c], power);
    lights.notCaptured += powerW * (1.0 - row.capturedFraction);
    lights.escaped += powerW * row.escapedFraction();
    lights.absorbed += powerW * row.backFaces;
    lights.absorbedByBackFaces += powerW * row.backFaces;
    lights.lightOutside += powerW * (row.escapedFraction() + row.backFaces);
  }
}

void CellSolver::State::exchange() {
  for (const PortalLink& link : links)
    cells[link.twinCell].solver->addPortalPower(link.twinPatch, cells[link.cell].solver->takePortalPower(link.patch));
}

void CellSolver::round() {
  State& s = *state_;
  const std::vector<int> shots = s.shotsThisRound(ledger());
  std::vector<int> active;
  for (int c = 0; c < cellCount(); ++c)
    if (shots[c] > 0 && !s.cells[c].solver->exhausted()) active.push_back(c);
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
  checkLedger(ledger(), iterations());
  s.exchange();
  checkLedger(ledger(), iterations());
}

bool CellSolver::exhausted() const {
  const State& s = *state_;
  const bool waiting = std::any_of(s.links.begin(), s.links.end(), [&](const PortalLink& l) {
    return channelSum(s.cells[l.cell].solver->portalPower(l.patch)) > 0.0;
  });
  return !waiting && std::all_of(s.cells.begin(), s.cells.end(), [](const CellState& c) { return c.solver->exhausted(); });
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
  for (const CellState& cell : s.cells) parts.push_back(&cell.solver->ledger());
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
  for (const PortalLink& link : s.links) total.unshot += channelSum(s.cells[link.cell].solver->portalPower(link.patch));
  return total;
}

int CellSolver::iterations() const {
  int n = 0;
  for (const CellState& cell : state_->cells) n += static_cast<int>(cell.solver->history().size());
  return n;
}

int CellSolver::rounds() const { return state_->rounds; }

namespace {

// Per building patch, what `perCell` gives for each cell's own patches.
template <typename PerCell>
std::vector<Rgb> gather(const std::vector<CellState>& cells, size_t patchCount, PerCell perCell) {
  std::vector<Rgb> out(patchCount, Rgb(0.0));
  for (const CellState& cell : cells) {
    const std::vector<Rgb> values = perCell(*cell.solver);
    for (size_t j = 0; j < cell.buildingPatch.size(); ++j) out[cell.buildingPatch[j]] = values[j];
  }
  return out;
}

}  // namespace

std::vector<Rgb> CellSolver::radiosity() const {
  return gather(state_->cells, state_->patches.size(), [](const ProgressiveSolver& s) { return s.radiosity(); });
}

std::vector<Rgb> CellSolver::displayRadiosity() const {
  return gather(state_->cells, state_->patches.size(), [](const ProgressiveSolver& s) { return s.displayRadiosity(); });
}

const std::vector<Patch>& CellSolver::patches() const { return state_->patches; }
int CellSolver::cellCount() const { return static_cast<int>(state_->cells.size()); }
int CellSolver::portalCount() const { return state_->portalCount; }
const ProgressiveSolver& CellSolver::cellSolver(int cell) const { return *state_->cells.at(static_cast<size_t>(cell)).solver; }
const SolveOptions& CellSolver::options() const { return state_->options; }
const CellSolveSettings& CellSolver::settings() const { return state_->settings; }

std::vector<CellFigures> CellSolver::cellFigures() const {
  const State& s = *state_;
  std::vector<CellFigures> figures;
  for (const CellState& cell : s.cells)
    figures.push_back({cell.name, static_cast<int>(cell.buildingPatch.size()), cell.portalPatches,
                       static_cast<int>(cell.solver->history().size()), cell.solver->ledger(), 0.0});
  for (const PortalLink& link : s.links)
    figures[link.cell].waitingW += channelSum(s.cells[link.cell].solver->portalPower(link.patch));
  return figures;
}

}  // namespace radmesh
