#include "solver/meshing/scene_summary.h"

#include <limits>

namespace radmesh {

SceneSummary summarizeScene(const Scene& scene, const std::vector<Patch>& patches, double cellM) {
  SceneSummary s;
  s.polygons = scene.polygons.size();
  s.patches = patches.size();
  s.materials = scene.materials.size();
  s.cellM = cellM;
  s.grids = gridsOf(scene);
  s.boundsMin = Vec3(std::numeric_limits<double>::infinity());
  s.boundsMax = -s.boundsMin;
  for (const Polygon& p : scene.polygons) {
    if (scene.materials[p.material].emits()) ++s.emitterPolygons;
    s.totalAreaM2 += polygonArea(p.vertices);
    for (const Vec3& v : p.vertices) {
      s.boundsMin = glm::min(s.boundsMin, v);
      s.boundsMax = glm::max(s.boundsMax, v);
    }
  }
  for (const Patch& p : patches)
    if (scene.materials[p.material].emits()) ++s.emitterPatches;
  s.lights = scene.lights.size();
  s.emittedPowerW = emittedPowerW(scene);
  return s;
}

}  // namespace radmesh
