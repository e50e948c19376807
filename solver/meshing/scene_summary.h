#pragma once
// The figures `radmesh info` prints and the viewer's panel shows: one function serves both.
#include <cstddef>
#include <vector>

#include "solver/meshing/grid_turn.h"
#include "solver/meshing/patch.h"
#include "solver/scene/scene.h"

namespace radmesh {

struct SceneSummary {
  std::size_t polygons = 0;
  std::size_t patches = 0;
  std::size_t materials = 0;
  std::size_t emitterPolygons = 0;
  std::size_t emitterPatches = 0;
  std::size_t lights = 0;  // lights without a patch (glTF's KHR_lights_punctual, --sun)
  Vec3 boundsMin{0.0};
  Vec3 boundsMax{0.0};
  double totalAreaM2 = 0.0;
  double emittedPowerW = 0.0;  // summed over RGB
  double cellM = 0.0;
  Grids grids;  // the meshing grids: the world's alone for a model along the axes
};

SceneSummary summarizeScene(const Scene& scene, const std::vector<Patch>& patches, double cellM);

}  // namespace radmesh
