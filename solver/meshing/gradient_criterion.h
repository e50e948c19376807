#pragma once
// The rule of adaptive subdivision's gradient criterion (--subdivide adaptive), in one place for
// the two that apply it: the host (markContrast, solver/radiosity/adaptive_split.h) and the mesh
// back end (markContrastOnMesh, solver/backends/mesh/mesh_contrast.h), which must mark the same
// elements. Here rather than in solver/radiosity/ because back ends do not include the solver.
#include <cmath>

namespace radmesh {

// The largest difference allowed between neighbours' reflected light: `contrast` times the
// brightest element's. A step the eye would see in a picture exposed for the brightest, where a
// relative step would also split the dim corners, whose errors no picture shows.
inline double contrastStep(double contrast, double brightest) { return contrast * brightest; }

// Whether an element whose reflected light is `light` differs from a neighbour's by more than
// `step`: the element is then marked, if it may split.
inline bool stepTooLarge(double light, double neighbourLight, double step) {
  return std::abs(light - neighbourLight) > step;
}

}  // namespace radmesh
