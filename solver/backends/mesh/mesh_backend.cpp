#include "solver/backends/mesh/mesh_backend.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <type_traits>

#include "emulator/front_end.h"
#include "emulator/memory_ledger.h"
#include "emulator/reduce.h"
#include "parallel/thread_pool.h"
#include "solver/backends/mesh/mesh_adaptive_mapping.h"
#include "solver/backends/mesh/mesh_contrast.h"
#include "solver/backends/mesh/mesh_element_split.h"
#include "solver/scene/scene_error.h"
#include "solver/projection/single_plane.h"
#include "solver/formfactors/sub_pixel_receivers.h"

namespace radmesh {

namespace {

const SolveOptions& checked(const SolveOptions& options, const MeshBackendOptions& mesh) {
  validateOptions(options);
  auto powerOfTwo = [](int x) { return x > 0 && (x & (x - 1)) == 0; };
  if (!powerOfTwo(mesh.peRows) || !powerOfTwo(mesh.peCols))
    throw OptionError("a mesh of " + std::to_string(mesh.peRows) + " x " + std::to_string(mesh.peCols) +
                      " PEs cannot sort on its torus: give it power-of-two sides (the MP-1's 64 x 64)");
  return options;
}

emu::MachineConfig machineConfig(const SolveOptions& options, const MeshBackendOptions& mesh) {
  if (const emu::Transport* t = options.meshTransport.get()) try {
      emu::blockOf({mesh.peRows, mesh.peCols}, t->rankGrid(), t->rankRow(), t->rankCol());
    } catch (const std::invalid_argument& e) {
      throw OptionError(fmt::format("--distributed over {} processes ({} x {}): {}; or give a --pe-grid they divide",
                                    t->rankGrid().size(), t->rankGrid().rows, t->rankGrid().cols, e.what()));
    }
  return {mesh.peRows, mesh.peCols, mesh.memoryBudgetBytes, ThreadPool::sizeFor(options.threads),
          options.meshTransport};
}

// The emulator's fix speaks of its MachineConfig; a user sets the machine with flags.
[[noreturn]] void refuseMachine(const emu::MemoryBudgetError& e) {
  const std::string what = e.what();
  throw OptionError(what.substr(0, what.find(" Fix:")) +
                    " Fix: give each PE more memory (a larger --pe-memory KB), spread the work over more PEs (a "
                    "larger --pe-grid), or give it less to hold (a smaller --resolution or fewer --shooters)");
}

// A patch's claim to shoot next, ordered as the solver orders shooters: more unshot power first,
// then the lower tie rank.
struct ShooterClaim {
  double powerW = 0.0;
  int tieRank = 0;
  bool operator<(const ShooterClaim& o) const {
    return powerW != o.powerW ? powerW < o.powerW : tieRank > o.tieRank;
  }
};

}  // namespace

MeshBackendOptions meshBackendOptions(const SolveOptions& options) {
  return {options.mapping, options.machine.rows, options.machine.cols, std::int64_t{options.machine.memoryKb} * 1024};
}

MeshBackend::MeshBackend(const Scene& scene, const std::vector<Patch>& patches,
                         const SolveOptions& options, const MeshBackendOptions& mesh)
    : MeshBackend(scene, patches, patches, options, mesh) {}

MeshBackend::MeshBackend(const Scene&, const std::vector<Patch>& patches, const std::vector<Patch>& receivers,
                         const SolveOptions& options, const MeshBackendOptions& mesh)
    : patches_(patches),
      receivers_(receivers),
      options_(checked(options, mesh)),
      mesh_(mesh),
      surface_(makeSinglePlane(options.resolution, options.ratio)),
      machine_(machineConfig(options, mesh)),
      patchesOnPe_(machine_, "patches"),
      hostPool_(options.threads) {
  layout_ = {static_cast<int>(receivers.size()), machine_.size()};
  // The patches spread out equally over the PE array (section 1.5); so do the elements, beside them.
  shooterLayout_ = {static_cast<int>(patches.size()), machine_.size()};
  const auto record = [](int j) { return PatchRecord{j}; };
  try {
    lay(patchesOnPe_, layout_, record);
    if (&receivers != &patches) {
      shootersOnPe_ = std::make_unique<emu::PeArray<PatchRecord>>(machine_, "shooting patches");
      lay(*shootersOnPe_, shooterLayout_, record);
    }
  } catch (const emu::MemoryBudgetError& e) {
    refuseMachine(e);
  }
  makeScanConversion();
}

void MeshBackend::makeScanConversion() {
  scan_ = std::make_unique<MeshScanConversion>(machine_, patches_, receivers_, patchesOnPe_, surface_.faces[0],
                                               sceneNearDepth(patches_));
}

MeshBackend::~MeshBackend() = default;

ProjectionSummary MeshBackend::projectionSummary() const {
  return {surface_.capturedFraction, surface_.tableSum};
}

std::shared_ptr<const ShotStats> MeshBackend::lastShotStats() const {
  return std::make_shared<const ShotStats>(shotStats(lastShot_));
}

void MeshBackend::beginIteration() {
  machine_.resetPeaks();
  lastShot_ = {};
  iterationStart_ = machine_.costs();
  iterationHostStart_ = std::chrono::steady_clock::now();
}

void MeshBackend::totalIteration() {
  lastShot_.counts = machine_.costs() - iterationStart_;
  lastShot_.emulatedSeconds = emu::emulatedSeconds(lastShot_.counts).total();
  lastShot_.hostSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - iterationHostStart_).count();
}

template <class Work>
auto MeshBackend::inPhase(const char* name, Work&& work) {
  // Destroyed in reverse order: the phase's clock stops, then the iteration is totalled.
  struct Total {
    MeshBackend& backend;
    ~Total() { backend.totalIteration(); }
  } total{*this};
  PhaseClock clock(machine_, lastShot_, name);
  return work();
}

MeshShot MeshBackend::runShot(std::span<const int> shooters, bool formFactors,
                              std::vector<std::vector<double>>* pixelFormFactors, MeshShotStats& stats) try {
  MeshShot shot;
  shot.shooters.assign(shooters.begin(), shooters.end());
  shot.mapping = PlaneMapping::uniform(mesh_.mapping, options_.resolution, mesh_.peRows, mesh_.peCols);
  {
    PhaseClock clock(machine_, stats, "projection");
    scan_->project(shot);
  }
  if (mesh_.mapping == MappingKind::Adaptive) {
    PhaseClock clock(machine_, stats, "adaptive mapping");
    shot.mapping = adaptiveMapping(machine_, shot, patchesOnPe_, options_.resolution);
  }
  ScanDepths depths = scan_->scanConvert(shot, stats);
  if (formFactors) {
    PhaseClock clock(machine_, stats, "form factors");
    *pixelFormFactors = meshFormFactors(machine_, *scan_, shot, surface_, layout_);
  }
  stats.depthA = std::move(depths.a);
  stats.depthB = std::move(depths.b);
  stats.passes = depths.passes;
  stats.depthAMax = *std::max_element(stats.depthA.begin(), stats.depthA.end());
  stats.depthBMax = *std::max_element(stats.depthB.begin(), stats.depthB.end());
  stats.depthAHist = depthHistogram(stats.depthA);
  stats.depthBHist = depthHistogram(stats.depthB);
  return shot;
} catch (const emu::MemoryBudgetError& e) {
  refuseMachine(e);
}

void MeshBackend::computeRows(std::span<const int> shooters, std::vector<FormFactorRow>& rows) {
  rows.clear();
  if (shooters.empty()) return;
  if (!shotPending_) beginIteration();  // called on its own: the record is of this shot alone
  shotPending_ = false;
  std::vector<std::vector<double>> formFactors;
  const MeshShot shot = runShot(shooters, true, &formFactors, lastShot_);
  totalIteration();
  for (int q = 0; q < static_cast<int>(shooters.size()); ++q)
    rows.push_back(assembleRow(shot, q, std::move(formFactors[q])));
}

FormFactorRow MeshBackend::assembleRow(const MeshShot& shot, int plane, std::vector<double> formFactors) {
  // The front end reads what each patch's PE made of it on this plane.
  struct Seen {
    int pe = 0;
    int patch = 0;
    bool seenFromFront = false;
    double areaPixels = 0.0, widthPixels = 0.0;  // 0 where not projected
    long long coveredPixels = 0;
  };
  std::vector<Seen> held;
  for (int j = 0; j < layout_.patches; ++j) {
    if (!machine_.holds(layout_.peOf(j))) continue;
    const PatchProjection& p = shot.projection(layout_.peOf(j), layout_.slotOf(j), plane);
    Seen s{layout_.peOf(j), j, p.seenFromFront};
    if (p.projected) s.areaPixels = p.setup.areaPixels, s.widthPixels = p.setup.widthPixels;
    if (p.projected && refinedAnalytically(s.areaPixels, s.widthPixels)) s.coveredPixels = coveredPixelCount(p.setup);
    held.push_back(s);
  }
  const auto n = static_cast<size_t>(layout_.patches);
  std::vector<char> seenFromFront(n, 0);
  std::vector<double> projectedAreaPixels(n, 0.0), projectedWidthPixels(n, 0.0);
  std::vector<long long> coveredPixels(n, 0), shownPixels(n, 0);
  for (const Seen& s : emu::gatherByPe(machine_, std::move(held)))
    seenFromFront[s.patch] = s.seenFromFront, projectedAreaPixels[s.patch] = s.areaPixels,
    projectedWidthPixels[s.patch] = s.widthPixels, coveredPixels[s.patch] = s.coveredPixels;
  if (options_.subPixelReceivers) {
    const ItemBuffer buffer = scan_->gatherItemBuffer(shot, plane);
    for (int id : buffer.items) if (id != ItemBuffer::kNone) ++shownPixels[id];
    if (!occluders_) occluders_.emplace(patches_);
    const ProjectedShot projected{receivers_, patches_[shot.shooters[plane]], surface_, {&buffer, 1},
                                  projectedAreaPixels, projectedWidthPixels, coveredPixels,
                                  shownPixels, *occluders_};
    refineSubPixelReceivers(projected, hostPool_, formFactors);
  }
  return radmesh::assembleRow(shot.shooters[plane], surface_.capturedFraction, formFactors, seenFromFront);
}

// The running counts are plain numbers: their bytes are the state, doubles bitwise.
static_assert(std::is_trivially_copyable_v<emu::CostCounts>);

std::string MeshBackend::machineState() const {
  const emu::CostCounts costs = machine_.costs();
  return std::string(reinterpret_cast<const char*>(&costs), sizeof costs);
}

void MeshBackend::restoreMachineState(const std::string& state) {
  if (state.size() != sizeof(emu::CostCounts))
    throw std::invalid_argument(fmt::format("the mesh back end's state is {} bytes, not {}", state.size(),
                                            sizeof(emu::CostCounts)));
  std::memcpy(&machine_.counters(), state.data(), state.size());
}

ItemBuffer MeshBackend::singlePlaneItemBuffer(int shooter) {
  const int shooters[] = {shooter};
  MeshShotStats stats;  // not part of any iteration
  const MeshShot shot = runShot(shooters, false, nullptr, stats);
  return scan_->gatherItemBuffer(shot, 0);
}

std::vector<int> MeshBackend::selectShooters(std::span<const double> unshotPowerW,
                                             std::span<const int> tieRank, int k) {
  refuseNaNUnshotPower(unshotPowerW);
  beginIteration();
  shotPending_ = true;
  return inPhase("shooter selection", [&] {
    emu::Plural<ShooterClaim> best(machine_, {}, "strongest claim");
    emu::Plural<int> bestPatch(machine_, -1, "strongest patch");
    const emu::PeArray<PatchRecord>& shootersOnPe = shootersOnPe_ ? *shootersOnPe_ : patchesOnPe_;
    std::vector<char> chosen(shooterLayout_.patches, 0);
    std::vector<int> shooters;
    for (int round = 0; round < k; ++round) {
      // Each PE finds its strongest patch not yet chosen, then one reduceMax over the mesh.
      emu::Plural<bool> has(machine_, false, "has a claim");
      const double slots = shooterLayout_.slotsPerPe();
      machine_.compute({slots, 2.0 * slots}, [&](int pe) {
        for (const PatchRecord& r : shootersOnPe.list(pe)) {
          const ShooterClaim claim{unshotPowerW[r.patch], tieRank[r.patch]};
          if (chosen[r.patch] || !(claim.powerW > 0.0)) continue;
          if (!has[pe] || best[pe] < claim) best[pe] = claim, bestPatch[pe] = r.patch, has[pe] = true;
        }
      });
      emu::ActiveScope scope(machine_, has);
      const emu::Located<ShooterClaim> top = emu::reduceMax(machine_, best);
      if (top.pe < 0) break;
      shooters.push_back(emu::readPe(bestPatch, top.pe));
      chosen[shooters.back()] = 1;
    }
    return shooters;
  });
}

std::vector<int> MeshBackend::rowIndexOf(const FormFactorRow& row) const {
  std::vector<int> index(layout_.patches, -1);
  for (std::size_t r = 0; r < row.receivers.size(); ++r) index[row.receivers[r]] = static_cast<int>(r);
  return index;
}

double MeshBackend::updateReceivers(const FormFactorRow& row, double flopsPerUpdate,
                                    const std::function<double(std::size_t)>& update) {
  return inPhase("radiosity update", [&] {
    const std::vector<int> receiverOf = rowIndexOf(row);
    emu::Plural<double> absorbed(machine_, 0.0, "absorbed power");
    const double slots = layout_.slotsPerPe();
    machine_.compute({flopsPerUpdate * slots, 2.0 * slots}, [&](int pe) {
      for (const PatchRecord& p : patchesOnPe_.list(pe))
        if (receiverOf[p.patch] >= 0) absorbed[pe] += update(receiverOf[p.patch]);
    });
    // Every process's front end keeps the whole solve: it updates the other processes' receivers too.
    for (int j = 0; j < layout_.patches; ++j)
      if (!machine_.holds(layout_.peOf(j)) && receiverOf[j] >= 0) update(receiverOf[j]);
    return emu::reduceAdd(machine_, absorbed);
  });
}

void MeshBackend::testReceivers(const FormFactorRow& row, double flopsPerTest, double flopsPerRay,
                                const std::function<int(std::size_t)>& test) {
  inPhase("shadow test", [&] {
    const std::vector<int> receiverOf = rowIndexOf(row);
    emu::Plural<double> rays(machine_, 0.0, "rays cast");
    const double slots = layout_.slotsPerPe();
    machine_.forEachActive(flopsPerTest * slots, [&](int pe) {
      for (const PatchRecord& p : patchesOnPe_.list(pe))
        if (receiverOf[p.patch] >= 0) rays[pe] += test(receiverOf[p.patch]);
    });
    // As in updateReceivers: every front end marks the other processes' receivers too, so that
    // every process splits the same elements.
    for (int j = 0; j < layout_.patches; ++j)
      if (!machine_.holds(layout_.peOf(j)) && receiverOf[j] >= 0) test(receiverOf[j]);
    const double most = emu::reduceMax(machine_, rays).value;
    machine_.chargeAlu({flopsPerTest * slots + flopsPerRay * most, 2.0 * slots});
  });
}

bool MeshBackend::markContrast(const std::vector<std::vector<int>>& neighbours, const std::vector<double>& reflected,
                               double contrast, const std::function<bool(int)>& canSplit,
                               std::vector<char>& split) try {
  inPhase("gradient test", [&] {
    markContrastOnMesh(machine_, patchesOnPe_, layout_, neighbours, reflected, contrast, canSplit, split);
  });
  return true;
} catch (const emu::MemoryBudgetError& e) {
  refuseMachine(e);
}

void MeshBackend::receiversSplit(std::span<const int> origin) try {
  inPhase("element split", [&] {
    const PatchLayout before = layout_;
    layout_ = {static_cast<int>(receivers_.size()), machine_.size()};
    scan_.reset();  // its buffers are free between shots: made again over the new elements below
    moveSplitElements(machine_, before, layout_, origin, patchesOnPe_);
    makeScanConversion();
  });
  shotPending_ = true;
} catch (const emu::MemoryBudgetError& e) {
  refuseMachine(e);
}

}  // namespace radmesh
