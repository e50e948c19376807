#pragma once
// From radiosity (W/m^2) to display: the exposure factor applied before sRGB encoding.
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

// The factor that maps the 95th-percentile vertex luminance (the solver's luminance(), in
// solver/io/mgf_color.h) to 0.9 (near white): lamps may clip,
// the room stays readable. 1 when nothing is lit yet.
double autoExposure(const std::vector<Rgb>& vertexB);

}  // namespace radmesh
