#pragma once
// Polygons a file lists twice. Exporters write exact copies (a face in two layers, a model pasted
// onto itself); radiosity then splits the light falling there between the copies by depth ties,
// one lit and the other black, and a bake that shares their vertices shows the floor at about 60 %
// of its brightness. Other tools draw such a copy as the one surface it is, so it is dropped.
#include <cstddef>
#include <string>

#include "solver/scene/scene.h"

namespace radmesh {

struct DoubledPolygons {
  std::size_t dropped = 0;
  std::string first;  // the first dropped polygon's origin, or its index
};

// Removes every polygon with the same corners, in the same turning order from any corner (so the
// same side faces out), and the same material as an earlier one; the earlier one stays.
DoubledPolygons dropDoubledPolygons(Scene& scene);

}  // namespace radmesh
