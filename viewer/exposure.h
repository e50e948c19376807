#pragma once
// From radiosity (W/m^2) to display: the exposure factor applied before sRGB encoding.
#include <vector>

#include "solver/bake/display_radiosity.h"

namespace radmesh {

// The most stops the automatic exposure goes either way, and `--exposure` (radmesh render's and
// radmesh-view's) and the panel's slider take: past the reach of a bake's floats (2^-149 to 2^128).
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

// The stops the panel's exposure slider spans.
struct StopsSpan {
  double low = -20.0, high = 20.0;
  bool operator==(const StopsSpan&) const = default;
};

// The slider's span once `stops` is to be shown on it: `shown` while it holds them, so that a drag,
// which stays inside, never moves it (a span that followed the value ran away under the mouse);
// else -20..20 if that holds them, else the 40 stops about them, within ±kMaxExposureStops. 40
// stops on the panel's 200-pixel slider are 0.2 EV a pixel, fine enough to set by eye (all 320
// would be 1.6); a value from elsewhere (--exposure 40, a dim early solve's automatic exposure, a
// Ctrl+click typed one) is shown where it is, not pinned at an end.
StopsSpan exposureSliderSpan(double stops, StopsSpan shown);

}  // namespace radmesh
