#pragma once
// A projection surface (the paper's section 1.2): planar faces above the shooter, each split into
// pixels that carry a delta form factor. The single plane has one face, the hemicube five.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "solver/projection/projection.h"

namespace radmesh {

struct ProjectionSurface {
  std::vector<ProjectionFace> faces;
  // Per face, per pixel (row-major): the delta form factor, scaled so that they sum to
  // capturedFraction exactly; energy bookkeeping then rests on the closed form.
  std::vector<std::vector<double>> deltaFormFactors;
  double capturedFraction = 1.0;  // closed form: the fraction of a diffuse shooter's power caught
  double tableSum = 1.0;          // the delta form factors' sum as sampled, before that scaling
  // The faces see all around a point (a point light's cube), not only above the shooter's plane.
  bool wholeSphere = false;
};

// A patch in the shooter's frame as the surface's projection takes it: the whole sphere's faces
// every patch, the others only a patch not wholly behind the shooter (inShooterView).
std::optional<LocalPolygon> inSurfaceView(const ProjectionSurface& surface, const Patch& shooter, const Patch& patch);

// Delta form factor of a pixel centred at face coordinates (a, b), of area pixelArea at depth 1.
using DeltaFormFactorFn = std::function<double(double a, double b, double pixelArea)>;

// The surface `make` returns for `key`, made once and kept while anything holds it: the back ends of
// a cells solve's cells (a hundred in a building) project onto one set of delta form factors, 1.6 MB
// for a hemicube at 256², not one each. Thread-safe.
std::shared_ptr<const ProjectionSurface> sharedSurface(const std::string& key,
                                                       const std::function<ProjectionSurface()>& make);

// Adds a face whose pixels carry df at their centres.
void addFace(ProjectionSurface& surface, const ProjectionFace& face, const DeltaFormFactorFn& df);
// Records the sampled sum and scales every delta form factor so that they sum to capturedFraction.
void scaleToCapturedFraction(ProjectionSurface& surface, double capturedFraction);

}  // namespace radmesh
