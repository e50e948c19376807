#include "solver/radiosity/solver_input.h"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "solver/scene/scene_error.h"

namespace radmesh {

namespace {

void requireFinite(const Scene& scene, const std::string& element, const char* what, const Vec3& v) {
  if (!isFinite(v))
    throw SceneError(scene.source, element, fmt::format("has a NaN or infinite {} ({}, {}, {})", what, v.x, v.y, v.z),
                     "give every vertex finite coordinates in metres");
}

}  // namespace

// The solver checks what it is handed as the loaders check files: a scene built in code or a
// patch list from elsewhere would otherwise turn into NaN radiosity or light from nowhere.
void validateSolverInput(const Scene& scene, const std::vector<Patch>& patches) {
  for (const Material& m : scene.materials) {
    const std::string element = fmt::format("material '{}'", m.name);
    for (int c = 0; c < 3; ++c) {
      if (!(m.rho[c] >= 0.0 && m.rho[c] <= 1.0))
        throw SceneError(scene.source, element, fmt::format("reflectance {} is outside [0, 1]", m.rho[c]),
                         "give each reflectance channel a value from 0 to 1");
      if (!(std::isfinite(m.emittance[c]) && m.emittance[c] >= 0.0))
        throw SceneError(scene.source, element, fmt::format("emittance {} is negative or not finite", m.emittance[c]),
                         "give emittance as a finite, non-negative exitance in W/m^2");
    }
  }
  for (size_t i = 0; i < scene.polygons.size(); ++i) {
    const Polygon& polygon = scene.polygons[i];
    const std::string element = polygonName(scene, i);
    for (const Vec3& v : polygon.vertices) requireFinite(scene, element, "vertex", v);
  }
  for (size_t i = 0; i < patches.size(); ++i) {
    const Patch& p = patches[i];
    const std::string element = fmt::format("patch {} (of polygon {})", i, p.polygon);
    if (p.vertexCount != 3 && p.vertexCount != 4)
      throw SceneError(scene.source, element, fmt::format("has {} vertices, not 3 or 4", p.vertexCount),
                       "mesh the polygon it came from into triangles and convex quads");
    if (!(std::isfinite(p.areaM2) && p.areaM2 > 0.0))
      throw SceneError(scene.source, element, fmt::format("has area {} m^2", p.areaM2),
                       "fix the polygon it came from, or mesh with another --cell");
    for (int k = 0; k < p.vertexCount; ++k) requireFinite(scene, element, "vertex", p.vertices[k]);
    requireFinite(scene, element, "centroid", p.centroid);
    requireFinite(scene, element, "normal", p.normal);
    if (p.material < 0 || p.material >= static_cast<int>(scene.materials.size()))
      throw SceneError(scene.source, element, fmt::format("refers to material {}, which does not exist", p.material),
                       "give the polygon it came from a defined material");
  }
  if (patches.empty())
    throw SceneError(scene.source, "the scene", "meshed into no patches", "give it polygons");
  validateLights(scene);
}

}  // namespace radmesh
