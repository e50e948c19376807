// A CellSolver made: the partition checked, every cell's scene and portal patches, the cells
// assigned to processes, and the lights' one shot over the whole building handed to the cells.
#include <algorithm>
#include <array>
#include <numeric>
#include <fmt/format.h>

#include "solver/formfactors/light_rows.h"
#include "solver/meshing/elements.h"
#include "solver/meshing/meshing.h"
#include "solver/projection/projection.h"
#include "solver/radiosity/cell_solver_state.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

using namespace cell_state;

namespace {

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
std::vector<double> loadOfCells(const std::vector<int>& patchCount, const std::vector<double>& lightW) {
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

void checkPortalBins(int portalBins) {
  if (portalBins < 0 || portalBins > kMaxPortalBins)
    throw OptionError(fmt::format("--portal-bins {} is out of range: give 0 or 1 (diffuse) up to {} (an N x N "
                                  "hemicube of direction bins)", portalBins, kMaxPortalBins));
}

CellSolver::CellSolver(const Scene& scene, std::vector<Patch> patches, const CellPartition& partition,
                       const SolveOptions& options, const CellSolveSettings& settings, CellRanks* ranks)
    : state_(std::make_unique<State>(scene, std::move(patches), options, settings, ranks)) {
  validateOptions(options);
  checkAdaptiveMinElement(options);
  if (options.until < 1.0)
    throw OptionError("--cells auto stops on the unshot power of the whole building alone: give --until 1 with "
                      "--until-unshot (the bake preset does), not a convergence C");
  if (settings.exchangeShots < 1) throw OptionError("--exchange-shots must be at least 1");
  checkPortalBins(settings.portalBins);
  State& s = *state_;
  // The building's elements within the limit, not only each cell's.
  if (options.subdivide != Subdivide::Off)
    checkElementBudget(s.patches, options.subdivide == Subdivide::Adaptive, options.minElementM);
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
  s.cellOf.resize(s.patches.size());
  for (int c = 0; c < cellCount; ++c)
    for (int j : own[c]) s.cellOf[j] = c;
  const std::vector<LightShot> lightShots = s.shootLights(scene);
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
  s.load = loadOfCells(patchCount, lightW);
  s.owner = assignCellsToRanks(s.load, ranks ? ranks->size() : 1);

  // Per cell: a scene of the polygons its patches came from (in the building's order) and its
  // portals, the building's materials and a black "portal" one (the solver passes portal light on).
  std::vector<std::array<int, 2>> portalFirstPatch(partition.portals.size(), {-1, -1});  // per side: A, B
  SolveOptions cellOptions = options;
  cellOptions.threads = 1;  // the cells run in parallel, each on one thread
  // The form-factor cache's budget is the whole solve's: each cell takes its share by patches.
  const double allPatches = std::accumulate(patchCount.begin(), patchCount.end(), 0.0);
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
    cellOptions.formFactorCacheBytes =
        static_cast<std::size_t>(static_cast<double>(options.formFactorCacheBytes) * patchCount[c] / allPatches);
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

// Each light's one shot over the whole building's receivers (solver/formfactors/light_rows.h), as
// the whole solve shoots it in its first iteration, cut by cell (receiveLights hands it on). The
// receivers are the patches, or with --subdivide uniform their elements, which each cell's solve
// makes alike (patch by patch, so a cell's are its patches' in the building's order); adaptive
// subdivision starts from the patches.
std::vector<LightShot> CellSolver::State::shootLights(const Scene& scene) {
  std::vector<LightShot> shots;
  if (scene.lights.empty()) return shots;
  const bool uniform = options.subdivide == Subdivide::Uniform;
  const Elements elements = uniform ? subdivideUniform(patches, options.minElementM) : Elements{};
  const std::vector<Patch>& receivers = uniform ? elements.elements : patches;
  std::vector<int> cellOfReceiver(receivers.size()), localOf(receivers.size()), next(cells.size(), 0);
  for (size_t e = 0; e < receivers.size(); ++e) {
    cellOfReceiver[e] = cellOf[uniform ? elements.patchOf[e] : e];
    localOf[e] = next[cellOfReceiver[e]]++;
  }
  LightRows rows(scene, receivers, options.resolution, sceneNearDepth(patches), pool);
  for (const Light& light : scene.lights) {
    LightShot& shot = shots.emplace_back();
    shot.power = lightPower(scene, light);
    shot.perCell.resize(cells.size());
    if (!(channelSum(shot.power) > 0.0)) continue;  // a dark light, or a beam with no window
    shot.row = rows.row(light);
    for (size_t r = 0; r < shot.row.receivers.size(); ++r) {  // ascending in the building, so in each cell
      FormFactorRow& part = shot.perCell[cellOfReceiver[shot.row.receivers[r]]];
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
    bookShotLosses(lights, shot.row, powerW, true);
  }
  if (options.subdivide != Subdivide::Adaptive || shots.empty()) return;
  std::vector<Rgb> powers;
  for (const LightShot& shot : shots) powers.push_back(shot.power);
  pool.parallelFor(static_cast<int>(cells.size()), [&](int c, int) {
    if (owns(c))
      cells[c].solver->splitAfterLights(powers, [this, c](int k, const std::vector<Patch>& receivers) {
        return lightRowOverCell(c, k, receivers);
      });
  });
}

// Light k's row over receivers of cell c (its solve's elements), shot over the building: the other
// cells' patches stand in their places and occlude, and the cell's portal elements, openings in the
// building, are left out (as in the lights' first shot, they get nothing). On the cell's thread.
FormFactorRow CellSolver::State::lightRowOverCell(int c, int k, const std::vector<Patch>& receivers) {
  const int portalMaterial = static_cast<int>(building.materials.size());  // the cell scene's last
  std::vector<Patch> shotOver;
  for (size_t j = 0; j < patches.size(); ++j)
    if (cellOf[j] != c) shotOver.push_back(patches[j]);
  const size_t others = shotOver.size();
  std::vector<int> receiverOf;
  for (size_t e = 0; e < receivers.size(); ++e)
    if (receivers[e].material != portalMaterial) shotOver.push_back(receivers[e]), receiverOf.push_back(static_cast<int>(e));
  ThreadPool one(1);
  const FormFactorRow over =
      lightRow(building, building.lights[k], shotOver, options.resolution, sceneNearDepth(patches), one);
  FormFactorRow row;
  for (size_t r = 0; r < over.receivers.size(); ++r)
    if (static_cast<size_t>(over.receivers[r]) >= others) {
      row.receivers.push_back(receiverOf[over.receivers[r] - others]);
      row.formFactors.push_back(over.formFactors[r]);
    }
  return row;
}
}  // namespace radmesh
