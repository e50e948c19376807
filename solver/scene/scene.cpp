#include "solver/scene/scene.h"

#include <cmath>
#include <string>

#include "solver/scene/scene_error.h"

namespace radmesh {

Vec3 newellNormal(const std::vector<Vec3>& v) {
  Vec3 n{0.0};
  // Relative to the first vertex so that a scene far from the origin keeps its precision.
  for (size_t i = 0; i < v.size(); ++i) {
    const Vec3 a = v[i] - v[0];
    const Vec3 b = v[(i + 1) % v.size()] - v[0];
    n += glm::cross(a, b);
  }
  return n;
}

double polygonArea(const std::vector<Vec3>& vertices) {
  return 0.5 * glm::length(newellNormal(vertices));
}

namespace {

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string describe(const Scene& scene, size_t index) {
  const Polygon& p = scene.polygons[index];
  return "polygon " + std::to_string(index) + (p.origin.empty() ? "" : " (" + p.origin + ")");
}

void validateMaterial(const Scene& scene, const Material& m) {
  const std::string element = "material '" + m.name + "'";
  for (int c = 0; c < 3; ++c) {
    if (!std::isfinite(m.rho[c]) || m.rho[c] < 0.0 || m.rho[c] >= 1.0)
      throw SceneError(scene.source, element,
                       "diffuse reflectance " + std::to_string(m.rho[c]) + " is outside [0, 1)",
                       "give each reflectance channel a value from 0 up to (not including) 1");
    if (!std::isfinite(m.emittance[c]) || m.emittance[c] < 0.0)
      throw SceneError(scene.source, element,
                       "emittance " + std::to_string(m.emittance[c]) + " is negative or not finite",
                       "give emittance as a finite, non-negative exitance in W/m^2");
  }
}

void validatePolygon(const Scene& scene, size_t index) {
  const Polygon& p = scene.polygons[index];
  const std::string element = describe(scene, index);
  if (p.vertices.size() < 3)
    throw SceneError(scene.source, element, "has fewer than 3 vertices",
                     "remove the polygon or give it at least 3 vertices");
  if (p.material < 0 || p.material >= static_cast<int>(scene.materials.size()))
    throw SceneError(scene.source, element, "refers to a material that does not exist",
                     "give the polygon a defined material");
  for (const Vec3& v : p.vertices)
    if (!finite(v))
      throw SceneError(scene.source, element, "has a NaN or infinite coordinate",
                       "give every vertex finite coordinates in metres");
  const Vec3 n = newellNormal(p.vertices);
  const double area = 0.5 * glm::length(n);
  double extent = 0.0;
  for (const Vec3& v : p.vertices) extent = std::max(extent, glm::length(v - p.vertices[0]));
  // Zero area relative to the polygon's own size: a scale-free test for collinear vertices.
  if (!(area > 1e-12 * extent * extent) || area == 0.0)
    throw SceneError(scene.source, element, "has zero area (its vertices are collinear or repeated)",
                     "remove the polygon or fix its vertices");
  const Vec3 unit = n / (2.0 * area);
  double worst = 0.0;
  for (const Vec3& v : p.vertices) worst = std::max(worst, std::abs(glm::dot(v - p.vertices[0], unit)));
  // Off-plane distance relative to size; 1e-3 admits float-rounded real models, not a bent quad.
  if (worst > 1e-3 * extent)
    throw SceneError(scene.source, element,
                     "is not planar (a vertex lies " + std::to_string(worst) + " m off its plane)",
                     "split it into triangles or flatten it");
}

}  // namespace

void validateGeometry(const Scene& scene) {
  if (scene.polygons.empty())
    throw SceneError(scene.source, "", "contains no polygons", "check that the file holds surfaces");
  for (const Material& m : scene.materials) validateMaterial(scene, m);
  for (size_t i = 0; i < scene.polygons.size(); ++i) validatePolygon(scene, i);
}

void validateScene(const Scene& scene) {
  validateGeometry(scene);
  if (!(emittedPowerW(scene) > 0.0))
    throw SceneError(scene.source, "", "has no emitter, so every radiosity would be zero",
                     "give at least one material a positive emittance, or light it by daylight through its "
                     "openings: --sky LUX, --sun AZIMUTH,ELEVATION[,LUX]");
}

double emittedPowerW(const Scene& scene) {
  double power = 0.0;
  for (const Polygon& p : scene.polygons) {
    const Rgb& e = scene.materials.at(p.material).emittance;
    power += polygonArea(p.vertices) * (e.r + e.g + e.b);
  }
  return power;
}

}  // namespace radmesh
