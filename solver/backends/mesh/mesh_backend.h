#pragma once
// Form factors on the emulated mesh-connected SIMD machine (emulator/): the paper's section 1.5
// as mesh programs, phase by phase, with the MP-1's costs and the item-buffer depths of section
// 1.6.1 recorded per shot. Agrees with the native back end: the same item buffers, and form
// factors equal up to the order of summation.
#include <chrono>
#include <memory>
#include <optional>
#include <span>

#include "emulator/mesh_machine.h"
#include "solver/backends/form_factor_backend.h"
#include "solver/backends/mesh/mesh_form_factors.h"
#include "solver/backends/mesh/mesh_scan_conversion.h"
#include "solver/backends/mesh/mesh_shot_stats.h"
#include "solver/meshing/occluders.h"
#include "solver/projection/plane_mapping.h"
#include "solver/projection/projection_surface.h"
#include "parallel/thread_pool.h"

namespace radmesh {

struct MeshBackendOptions {
  MappingKind mapping = MappingKind::Hierarchical;
  int peRows = 64;  // the paper's 4096-PE MP-1
  int peCols = 64;
  std::int64_t memoryBudgetBytes = 16 * 1024;
};

// The mapping and the machine SolveOptions choose (--mapping, --pe-grid, --pe-memory).
MeshBackendOptions meshBackendOptions(const SolveOptions& options);

class MeshBackend final : public FormFactorBackend {
 public:
  // Throws OptionError for invalid options, a projection other than the single plane (the
  // paper's) or a mesh whose sides are not powers of two. The scene is not needed beyond its
  // patches (kept for the factory's common signature).
  MeshBackend(const Scene& scene, const std::vector<Patch>& patches, const SolveOptions& options,
              const MeshBackendOptions& mesh = {});
  // Patches shoot, `receivers` receive (the elements of solver/meshing/elements.h): the PEs hold
  // the receivers for the projection and the radiosity update, and the patches for the shooter
  // selection; rows and item buffers index receivers.
  MeshBackend(const Scene& scene, const std::vector<Patch>& patches, const std::vector<Patch>& receivers,
              const SolveOptions& options, const MeshBackendOptions& mesh = {});
  ~MeshBackend() override;

  // All shooters' planes are mapped onto the mesh at once (the paper's section 1.7).
  void computeRows(std::span<const int> shooters, std::vector<FormFactorRow>& rows) override;
  ProjectionSummary projectionSummary() const override;
  ItemBuffer singlePlaneItemBuffer(int shooter) override;
  // The last iteration's record (selection, shot, update) for every consumer.
  std::shared_ptr<const ShotStats> lastShotStats() const override;
  std::string machineState() const override;
  void restoreMachineState(const std::string& state) override;

  // The shooting-patch selection phase on the mesh: k reduceMax over the patches' unshot power.
  // Begins the iteration's record: the next computeRows and updateReceivers add to it.
  std::vector<int> selectShooters(std::span<const double> unshotPowerW, std::span<const int> tieRank,
                                  int k) override;
  // Each PE updates the receivers it holds (SIMD: every PE steps through all its patch slots),
  // then one reduceAdd sums the absorbed power.
  double updateReceivers(const FormFactorRow& row, double flopsPerUpdate,
                         const std::function<double(std::size_t)>& update) override;
  // Each PE tests the receivers it holds; one reduceMax gives the array control unit the most
  // rays any PE casts, and the machine steps that many (phase "shadow test").
  void testReceivers(const FormFactorRow& row, double flopsPerTest, double flopsPerRay,
                     const std::function<int(std::size_t)>& test) override;
  // Each PE marks its elements (mesh_contrast.h), and the front end reads the marks.
  bool markContrast(const std::vector<std::vector<int>>& neighbours, const std::vector<double>& reflected,
                    double contrast, const std::function<bool(int)>& canSplit, std::vector<char>& split) override;
  // The elements lie on the PEs cyclically again, in the new order: each parent's PE makes its
  // children (an unsplit element is its own), and every one whose PE changes is routed to its
  // new PE and slot, as many router sends as the busiest PE makes elements (phase "element
  // split"). Old and new records share the PEs' memory while they move, within the budget. The
  // children's shots that follow (the solver's regathering) count in the same iteration.
  void receiversSplit(std::span<const int> origin) override;

  const MeshShotStats& lastShot() const { return lastShot_; }
  const emu::MeshMachine& machine() const { return machine_; }
  const MeshBackendOptions& meshOptions() const { return mesh_; }

 private:
  // Runs the phases up to the z-buffer (and the form factors when asked) for the shooters,
  // adding their phases and depths to stats.
  MeshShot runShot(std::span<const int> shooters, bool formFactors,
                   std::vector<std::vector<double>>* pixelFormFactors, MeshShotStats& stats);
  // lastShot_ as a new iteration's record from now; totalIteration() brings its totals up to now.
  void beginIteration();
  void totalIteration();
  // Runs work() as the iteration's phase `name` (its cost added to lastShot_) and totals;
  // returns what work() returns, if anything.
  template <class Work> auto inPhase(const char* name, Work&& work);
  FormFactorRow assembleRow(const MeshShot& shot, int plane, std::vector<double> formFactors);
  // Per receiver, its index in the row (-1 when not in it): where a PE finds its receiver's entry.
  std::vector<int> rowIndexOf(const FormFactorRow& row) const;
  // The scan conversion over the receivers as they are now.
  void makeScanConversion();

  const std::vector<Patch>& patches_;
  const std::vector<Patch>& receivers_;  // patches_ itself, or their elements
  SolveOptions options_;
  MeshBackendOptions mesh_;
  ProjectionSurface surface_;
  PatchLayout layout_;  // of the receivers
  emu::MeshMachine machine_;
  emu::PeArray<PatchRecord> patchesOnPe_;  // the receivers
  // The shooting patches, when elements receive (null when patches do: patchesOnPe_ holds them).
  std::unique_ptr<emu::PeArray<PatchRecord>> shootersOnPe_;
  PatchLayout shooterLayout_;
  std::unique_ptr<MeshScanConversion> scan_;
  ThreadPool hostPool_;  // the sub-pixel refinement (solver/formfactors/sub_pixel_receivers.h) runs on the host
  std::optional<Occluders> occluders_;  // patches_, for it; made when a shot first needs them
  MeshShotStats lastShot_;
  emu::CostCounts iterationStart_;  // the machine's counts when lastShot_ began
  std::chrono::steady_clock::time_point iterationHostStart_;
  bool shotPending_ = false;  // shooters were selected: the next computeRows is their shot
};

}  // namespace radmesh
