#pragma once
// Form factors on the host CPU: the single plane or the hemicube with item buffers, or analytic
// point-to-polygon form factors for convex enclosures. The oracle the mesh back end must match.
#include <memory>
#include <optional>

#include "solver/formfactors/sub_pixel_receivers.h"
#include "solver/projection/environment_projection.h"
#include "solver/backends/form_factor_backend.h"
#include "parallel/thread_pool.h"

namespace radmesh {

class NativeBackend final : public FormFactorBackend {
 public:
  NativeBackend(const Scene& scene, const std::vector<Patch>& patches, const SolveOptions& options);
  // Patches shoot, their elements receive (solver/meshing/elements.h): rows and item buffers index
  // elements.elements. With resolvedElementRows(options) Share, the projection holds the patches and rows
  // share their form factors among the elements (solver/formfactors/element_shares.h).
  NativeBackend(const Scene& scene, const std::vector<Patch>& patches, const Elements& elements,
                const SolveOptions& options);
  ~NativeBackend() override;

  void computeRows(std::span<const int> shooters, std::vector<FormFactorRow>& rows) override;
  ProjectionSummary projectionSummary() const override;
  void binDirections(std::span<const int> shooters, int n) override;

  ItemBuffer singlePlaneItemBuffer(int shooter) override;
  // The per-receiver buffers sized anew; the projections keep their surfaces and re-read the receivers.
  void receiversSplit(std::span<const int> origin) override;
  void releaseScratch() override;

  double nearDepth() const { return nearDepth_; }

 private:
  NativeBackend(const Scene& scene, const std::vector<Patch>& patches, const std::vector<Patch>& receivers,
                const Elements* elements, const SolveOptions& options);
  // The per-receiver buffers, and the projection over what it z-buffers as it is now (made on the first call).
  void takeReceivers();
  // Whether a shot's pixel sums are refined (sub_pixel_receivers.h). Not a directional shooter's:
  // its light goes by its pixels' direction bins, each to no more than the bin's directions catch
  // (portal_power.cpp), and refined entries would not fit them.
  bool refinesRow(int shooter) const;
  // The receivers' entries of a shot the projection made over the patches (shares_).
  void shareShot(EnvironmentProjection& projection, int shooter);
  FormFactorRow projectedRow(EnvironmentProjection& projection, int shooter);
  FormFactorRow analyticRow(int shooter);
  // A directional shooter's split by bin: from the item buffers of its projection, or analytic.
  void addPixelBins(const EnvironmentProjection& projection, FormFactorRow& row) const;
  void addAnalyticBins(int shooter, FormFactorRow& row) const;
  // The shot's projection as the sub-pixel receivers see it.
  ProjectedShot shotOf(const EnvironmentProjection& projection, int shooter, const std::vector<Patch>& receivers);
  // The receiver a shot from `shooter` skips: itself when patches receive, none when elements do.
  int skipOf(int shooter) const { return &receivers_ == &patches_ ? shooter : -1; }
  // The direction bins of the pixels where each patch is seen, before shares_ hands them to elements.
  void addPatchPixelBins(const EnvironmentProjection& projection, const std::vector<char>& seenFromFront,
                         FormFactorRow& row) const;

  const Scene& scene_;
  const std::vector<Patch>& patches_;
  const std::vector<Patch>& receivers_;  // patches_ itself, or their elements
  const Elements* elements_;             // null when patches receive
  bool shares_;                          // the projection holds patches_, rows their elements' shares
  SolveOptions options_;
  double nearDepth_;
  ThreadPool pool_;
  std::unique_ptr<EnvironmentProjection> projection_;  // null for --projection analytic
  std::unique_ptr<EnvironmentProjection> singlePlane_;  // made when first asked for
  std::vector<double> formFactors_;                     // per receiver, this shot
  std::vector<double> patchFormFactors_;                // shares_: per patch, this shot
  std::vector<char> patchSeenFromFront_;                // shares_: per patch, this shot
  std::vector<char> seenFromFront_;                     // per receiver, this shot
  std::optional<Occluders> occluders_;                   // patches_, made when a shot first needs them
  int binsN_ = 0;                                       // binDirections' n
  std::vector<char> directional_;                       // per patch: its rows split by bin
  std::vector<std::vector<int>> pixelBin_;              // per face, per pixel: the bin of its centre
  std::vector<double> binTotals_;                       // per bin: its pixels' delta form factors, or closed form
};

}  // namespace radmesh
