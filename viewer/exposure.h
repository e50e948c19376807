#pragma once
// From radiosity (W/m^2) to display: the exposure factor applied before sRGB encoding.
#include <vector>

#include "solver/bake/display_radiosity.h"

namespace radmesh {

// The most stops the automatic exposure goes either way, and `radmesh render --exposure` takes: past
// the reach of a bake's floats (2^-149 to 2^128).
inline constexpr double kMaxExposureStops = 160.0;

// The factor that maps the 95th percentile of luminance (the solver's luminance(), in
// solver/io/mgf_color.h), weighted by surface area, to 0.7 (below white). Weighing by area, not
// by vertex, keeps the many small polygons of a detailed scene (books, a keyboard) from setting
// the exposure of its walls; the lights, a few per cent of the area, stay above the percentile and
// clip, and nearly nothing else does. The same for every view, so that it does not pump while
// walking. Early in a solve, while most is dark, the brightest triangle sets it; 1 when nothing is
// lit yet. Clamped to kMaxExposureStops: a solve's doubles go far below a float's reach, and
// 1e-300 W/m^2 had made it +1010 EV.
double autoExposure(const DisplayMesh& mesh, const std::vector<Rgb>& vertexB);

}  // namespace radmesh
