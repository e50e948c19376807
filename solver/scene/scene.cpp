#include "solver/scene/scene.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <tuple>

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

double totalArea(const std::vector<Polygon>& polygons) {
  double area = 0.0;
  for (const Polygon& p : polygons) area += polygonArea(p.vertices);
  return area;
}

bool hasZeroArea(const std::vector<Vec3>& vertices) {
  if (vertices.empty()) return true;
  const double area = polygonArea(vertices);
  double extent = 0.0;
  for (const Vec3& v : vertices) extent = std::max(extent, glm::length(v - vertices[0]));
  // Zero area relative to the polygon's own size: a scale-free test for collinear vertices.
  return !(area > 1e-12 * extent * extent) || area == 0.0;
}

std::pair<Vec3, Vec3> perpendicularAxes(const Vec3& n) {
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(n[k]) < std::abs(n[axis])) axis = k;
  Vec3 u{0.0};
  u[axis] = 1.0;
  u = glm::normalize(u - n * glm::dot(u, n));
  return {u, glm::cross(n, u)};
}

double spotFalloff(const Light& spot, double cosTheta) {
  const double cosOuter = std::cos(spot.outerConeRad);
  const double band = std::cos(spot.innerConeRad) - cosOuter;
  const double t = std::clamp((cosTheta - cosOuter) / band, 0.0, 1.0);
  return t * t;
}

BoundingBox boundingBox(const std::vector<Vec3>& points) {
  BoundingBox box{Vec3(std::numeric_limits<double>::max()), Vec3(-std::numeric_limits<double>::max())};
  for (const Vec3& v : points) {
    box.low = glm::min(box.low, v);
    box.high = glm::max(box.high, v);
  }
  return box;
}

BoundingBox boundingBox(const std::vector<Polygon>& polygons) {
  BoundingBox box = boundingBox(std::vector<Vec3>{});
  for (const Polygon& p : polygons) {
    const BoundingBox b = boundingBox(p.vertices);
    box = {glm::min(box.low, b.low), glm::max(box.high, b.high)};
  }
  return box;
}

ParallelWindow parallelWindow(const Scene& scene, const Vec3& direction) {
  const auto [low, high] = boundingBox(scene.polygons);
  ParallelWindow w;
  std::tie(w.u, w.v) = perpendicularAxes(direction);
  w.a0 = w.b0 = std::numeric_limits<double>::max();
  w.a1 = w.b1 = -std::numeric_limits<double>::max();
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 c{corner & 1 ? high.x : low.x, corner & 2 ? high.y : low.y, corner & 4 ? high.z : low.z};
    w.a0 = std::min(w.a0, glm::dot(c, w.u));
    w.a1 = std::max(w.a1, glm::dot(c, w.u));
    w.b0 = std::min(w.b0, glm::dot(c, w.v));
    w.b1 = std::max(w.b1, glm::dot(c, w.v));
  }
  return w;
}

Rgb lightPower(const Scene& scene, const Light& light) {
  switch (light.type) {
    case LightType::Point: return 4.0 * std::numbers::pi * light.intensity;
    case LightType::Spot: {
      const double cosInner = std::cos(light.innerConeRad);
      const double cosOuter = std::cos(light.outerConeRad);
      return 2.0 * std::numbers::pi * ((1.0 - cosInner) + (cosInner - cosOuter) / 3.0) * light.intensity;
    }
    case LightType::Directional: return parallelWindow(scene, light.direction).areaM2() * light.intensity;
  }
  return Rgb(0.0);
}

std::string polygonName(const Scene& scene, size_t index) {
  const Polygon& p = scene.polygons[index];
  return "polygon " + std::to_string(index) + (p.origin.empty() ? "" : " (" + p.origin + ")");
}

namespace {

// What an emitter sends, past kMaxEmitted or above 0 but under kMinEmitted: refused, for every format alike.
void requireTrustedEmission(double emitted, const char* unit, const std::string& file, const std::string& element,
                            const char* what) {
  const std::string units = "MGF's ed is in lm/m^2, glTF's emission in W/m^2, a glTF light's intensity in candela "
                            "(lux for a directional light)";
  if (trustedEmission(emitted)) return;
  if (!(emitted < kMinEmitted))  // past kMaxEmitted, or not a number
    throw SceneError(file, element,
                     fmt::format("emits {:g} {}, more than the {:g} {} radmesh trusts (no real light comes near; a "
                                 "solve would overflow the bake's radiosities)",
                                 emitted, unit, kMaxEmitted, unit),
                     fmt::format("lower its {} to a real light's: {}", what, units));
  throw SceneError(file, element,
                   fmt::format("emits {:g} {}, less than the {:g} {} radmesh trusts (no real light comes near; a "
                               "solve's radiosities would fall below what the bake's floats hold: a black picture)",
                               emitted, unit, kMinEmitted, unit),
                   fmt::format("raise its {} to a real light's, or make it 0 if it is no light: {}", what, units));
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
  requireTrustedEmission(std::max({m.emittance.r, m.emittance.g, m.emittance.b}), "W/m^2", scene.source, element,
                         "emittance");
}

void validatePolygon(const Scene& scene, size_t index) {
  const Polygon& p = scene.polygons[index];
  const std::string element = polygonName(scene, index);
  if (p.vertices.size() < 3)
    throw SceneError(scene.source, element, "has fewer than 3 vertices",
                     "remove the polygon or give it at least 3 vertices");
  if (p.material < 0 || p.material >= static_cast<int>(scene.materials.size()))
    throw SceneError(scene.source, element, "refers to a material that does not exist",
                     "give the polygon a defined material");
  for (const Vec3& v : p.vertices)
    if (!isFinite(v))
      throw SceneError(scene.source, element, "has a NaN or infinite coordinate",
                       "give every vertex finite coordinates in metres");
  if (hasZeroArea(p.vertices))
    throw SceneError(scene.source, element, "has zero area (its vertices are collinear or repeated)",
                     "remove the polygon or fix its vertices");
  const Vec3 n = newellNormal(p.vertices);
  const double area = 0.5 * glm::length(n);
  double extent = 0.0;
  for (const Vec3& v : p.vertices) extent = std::max(extent, glm::length(v - p.vertices[0]));
  const Vec3 unit = n / (2.0 * area);
  double worst = 0.0;
  for (const Vec3& v : p.vertices) worst = std::max(worst, std::abs(glm::dot(v - p.vertices[0], unit)));
  // Off-plane distance relative to size; 1e-3 admits float-rounded real models, not a bent quad.
  if (worst > 1e-3 * extent)
    throw SceneError(scene.source, element,
                     "is not planar (a vertex lies " + std::to_string(worst) + " m off its plane)",
                     "split it into triangles or flatten it");
}

bool finiteNonNegative(const Rgb& c) { return isFinite(c) && c.r >= 0.0 && c.g >= 0.0 && c.b >= 0.0; }

void validateLight(const Scene& scene, const Light& light) {
  if (!finiteNonNegative(light.intensity))
    throw SceneError(scene.source, light.name,
                     "has a negative, NaN or infinite intensity (" + std::to_string(light.intensity.r) + ", " +
                         std::to_string(light.intensity.g) + ", " + std::to_string(light.intensity.b) + ")",
                     "give the light a finite, non-negative intensity and colour");
  requireTrustedEmission(channelSum(lightPower(scene, light)), "W", scene.source, light.name, "intensity");
  if (light.type != LightType::Directional && !isFinite(light.position))
    throw SceneError(scene.source, light.name, "has a NaN or infinite position",
                     "give its node a finite transform");
  if (light.type != LightType::Point &&
      !(isFinite(light.direction) && std::abs(glm::length(light.direction) - 1.0) < 1e-9))
    throw SceneError(scene.source, light.name, "has no direction (zero, NaN or not a unit vector)",
                     "give its node a rotation, not a zero scale");
  if (light.type == LightType::Spot &&
      !(light.innerConeRad >= 0.0 && light.innerConeRad < light.outerConeRad &&
        light.outerConeRad <= std::numbers::pi / 2))
    throw SceneError(scene.source, light.name,
                     "has cone angles inner " + std::to_string(light.innerConeRad) + ", outer " +
                         std::to_string(light.outerConeRad) + " rad",
                     "give 0 <= innerConeAngle < outerConeAngle <= pi/2");
}

// A model far from the origin for its size keeps too few digits of its own coordinates: 1e12 m out,
// a 2 m box is known to 1e-4 m and its emitted power came out 0.02 % off, without a word. At site
// coordinates (5e6 m) a 5 m building is known to 2e-10 of its size, fifty times finer than asked.
constexpr double kLeastCoordinatePrecision = 1e-8;  // of the model's size

void validatePrecision(const Scene& scene) {
  const BoundingBox box = boundingBox(scene.polygons);
  const Vec3 extent = box.high - box.low;
  const double size = std::max({extent.x, extent.y, extent.z});
  const Vec3 far = glm::max(glm::abs(box.low), glm::abs(box.high));
  const double farthest = std::max({far.x, far.y, far.z});
  const double knownTo = farthest * std::numeric_limits<double>::epsilon();
  if (!(knownTo <= kLeastCoordinatePrecision * size))
    throw SceneError(scene.source, "",
                     fmt::format("lies {:.3g} m from the origin, where a coordinate is known to {:.2g} m only, {:.2g} "
                                 "of the model's {:.4g} m size",
                                 farthest, knownTo, size > 0.0 ? knownTo / size : 1.0, size),
                     "move the model near the origin (MGF: xf -t; glTF: the root node's translation), or give its "
                     "coordinates from a point on the site");
}

}  // namespace

void validateGeometry(const Scene& scene) {
  if (scene.polygons.empty())
    throw SceneError(scene.source, "", "contains no polygons", "check that the file holds surfaces");
  validatePrecision(scene);
  for (const Material& m : scene.materials) validateMaterial(scene, m);
  for (size_t i = 0; i < scene.polygons.size(); ++i) validatePolygon(scene, i);
  validateLights(scene);
}

void validateScene(const Scene& scene) {
  validateGeometry(scene);
  if (emittedPowerW(scene) > 0.0) return;
  // Lights that send nothing in: a beam along a flat model (it meets no area), a light of no power.
  if (!scene.lights.empty())
    throw SceneError(scene.source, scene.lights.front().name,
                     fmt::format("{} light(s) but no emitter, and they send no light into the model (a sun or "
                                 "directional light along a flat model meets none of its area)",
                                 scene.lights.size()),
                     "turn the light (--sun's elevation or azimuth) so that it shines onto the surfaces, or give "
                     "a material a positive emittance");
  throw SceneError(scene.source, "", "has no emitter, so every radiosity would be zero",
                   "give at least one material a positive emittance, or light it by daylight through its "
                   "openings: --sky LUX, --sun AZIMUTH,ELEVATION[,LUX]");
}

void validateLights(const Scene& scene) {
  for (const Light& light : scene.lights) validateLight(scene, light);
}

double emittedPowerW(const Scene& scene) {
  double power = 0.0;
  for (const Polygon& p : scene.polygons) {
    const Rgb& e = scene.materials.at(p.material).emittance;
    power += polygonArea(p.vertices) * channelSum(e);
  }
  for (const Light& light : scene.lights) {
    power += channelSum(lightPower(scene, light));
  }
  return power;
}

}  // namespace radmesh
