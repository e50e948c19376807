#pragma once
// The materials the built-in office and the generated building share, so the building's rooms
// look like the office they copy.
#include "solver/scene/scene.h"

namespace radmesh::interior {

inline const Material kWallPaint{"wall paint", {0.72, 0.70, 0.65}};
inline const Material kCeilingTile{"ceiling tile", {0.80, 0.80, 0.78}};
inline const Material kCarpet{"carpet", {0.22, 0.24, 0.28}};
// A fluorescent troffer's diffuser: 10 W/m^2 per channel, slightly warm.
inline const Material kLightPanel{"light panel", {0.80, 0.80, 0.80}, {10.0, 9.6, 8.8}};
inline const Material kDoorFrame{"door frame", {0.60, 0.58, 0.52}};
inline const Material kOak{"oak", {0.55, 0.38, 0.22}};
inline const Material kBeech{"beech", {0.62, 0.48, 0.30}};
inline const Material kChairFabric{"chair fabric", {0.15, 0.22, 0.45}};
inline const Material kCabinetEnamel{"cabinet enamel", {0.55, 0.56, 0.58}};

}  // namespace radmesh::interior
