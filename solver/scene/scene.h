#pragma once
// The scene: planar polygons in metres with diffuse materials. What importers produce and the
// mesher consumes; nothing here knows about patches or light transport.
#include <glm/glm.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace radmesh {

using Vec3 = glm::dvec3;
using Rgb = glm::dvec3;  // linear RGB, one value per channel
// The ledger, the shooting order and the stopping rule weigh power summed over the channels.
inline double channelSum(const Rgb& c) { return c.r + c.g + c.b; }
inline bool isFinite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Photometric to radiometric, in every reader and option that takes lumens, candela or lux (MGF's
// `ed`, IES luminaires, glTF lights, --sun): 179 lm/W, the luminous efficacy of equal-energy white
// that Radiance (MGF's origin) uses. One white watt per channel per 179 lm (docs/scene-formats.md).
inline constexpr double kWhiteEfficacyLmPerW = 179.0;

// What a reflectance of 1 or more is lowered to, in every reader: rho = 1 would never let light
// die out, and exporters write 1 for white.
inline constexpr double kHighestReflectance = 0.99;

// Past this distance from the origin (m) lengths and areas overflow, or rounding swallows the model:
// every reader refuses a point placed farther (MGF where it is given, glTF after the node transforms).
inline constexpr double kMaxCoordinate = 1e30;
inline bool withinCoordinateBound(const Vec3& p) {
  return std::abs(p.x) <= kMaxCoordinate && std::abs(p.y) <= kMaxCoordinate && std::abs(p.z) <= kMaxCoordinate;
}

// The most an emitter may send that radmesh trusts: a material's exitance in W/m^2 per channel, a
// light's power in W. Beyond it (no real light comes within twenty orders of it) a solve carries
// the number into radiosities that a bake's 32-bit floats cannot hold.
inline constexpr double kMaxEmitted = 1e30;
// The least an emitter may send above nothing, in the same units: below it a solve's radiosities
// fall under what a bake's 32-bit floats hold (1e-38 and less), and its picture comes out black.
inline constexpr double kMinEmitted = 1e-30;
// An emitter's figure that radmesh trusts: nothing, or kMinEmitted to kMaxEmitted (false for NaN).
inline bool trustedEmission(double emitted) {
  return emitted == 0.0 || (emitted >= kMinEmitted && emitted <= kMaxEmitted);
}

struct Material {
  std::string name;
  Rgb rho{0.0};        // diffuse reflectance per channel, each in [0, 1)
  Rgb emittance{0.0};  // radiant exitance, W/m^2 per channel
  // The sky in a window (--sky): it emits and reflects nothing, and the lights (the sun) shine
  // through it as through the opening it fills.
  bool skyOpening = false;
  bool emits() const { return emittance.r > 0.0 || emittance.g > 0.0 || emittance.b > 0.0; }
};

struct Polygon {
  std::vector<Vec3> vertices;  // metres; counter-clockwise seen from the front (lit) side
  int material = 0;            // index into Scene::materials
  std::string origin;          // where it came from, for messages: "line 120: f", "mesh 'desk'"
};

// A light without a patch (glTF's KHR_lights_punctual, the sun): its first shot is a projection
// from the light itself (solver/formfactors/light_rows.h), after which it is done.
enum class LightType { Point, Spot, Directional };

struct Light {
  std::string name;  // for messages: "light 0 'lamp' (node 3)", "--sun"
  LightType type = LightType::Point;
  Vec3 position{0.0};           // point and spot, metres
  Vec3 direction{0.0, 0.0, -1.0};  // spot and directional: the unit direction the light travels
  // Point and spot: radiant intensity, W/sr per channel (on the spot's axis). Directional:
  // irradiance on a surface normal to the light, W/m^2 per channel.
  Rgb intensity{0.0};
  double innerConeRad = 0.0;    // spot: full intensity within this angle of the axis
  double outerConeRad = std::numbers::pi / 4;  // spot: none beyond it (glTF's default), at most pi / 2
};

struct Scene {
  std::string source;  // file path or built-in name, for messages
  std::vector<Material> materials;
  std::vector<Polygon> polygons;
  std::vector<Light> lights;
  // 0 x, 1 y, 2 z: glTF's y as it defines, the built-in rooms' z; MGF's, which it does not say, and
  // --up's are set by loadScene (solver/io/scene_loader.h, solver/scene/up_axis.h).
  int upAxis = 2;
  std::string file{};  // the file it was read from (a built-in's asset too), never written over; empty: made in code
};

// The axis-aligned box around the polygons' vertices; low above high when there are none.
struct BoundingBox {
  Vec3 low, high;
};
BoundingBox boundingBox(const std::vector<Polygon>& polygons);
BoundingBox boundingBox(const std::vector<Vec3>& points);

// Newell's normal: its length is twice the polygon's area, robust for non-convex polygons.
Vec3 newellNormal(const std::vector<Vec3>& vertices);
double polygonArea(const std::vector<Vec3>& vertices);
// The polygons' areas summed.
double totalArea(const std::vector<Polygon>& polygons);
// No area for the polygon's own size (its vertices collinear or repeated): validateScene refuses it.
bool hasZeroArea(const std::vector<Vec3>& vertices);

// Unit axes u, v such that (u, v, n) is right-handed and orthonormal, for a unit n: u is the world
// axis least aligned with n, projected into the plane normal to n (deterministic).
std::pair<Vec3, Vec3> perpendicularAxes(const Vec3& n);

// Throws SceneError for input that cannot be solved: no polygons, NaN or infinite coordinates,
// fewer than 3 vertices, zero area, non-planar polygons, rho outside [0,1), negative or non-finite
// emittance or one past kMaxEmitted (or above 0 but under kMinEmitted), a material index out of range,
// a light with a non-finite or negative intensity or a power past kMaxEmitted (or above 0 but under
// kMinEmitted), a zero direction or cone angles outside
// 0 <= inner < outer <= pi/2.
void validateGeometry(const Scene& scene);
// How messages name a scene polygon: "polygon N", and where it came from when known.
std::string polygonName(const Scene& scene, size_t index);
// The same, and no emitter at all, neither an emitting material nor a light (the message points to
// daylight).
void validateScene(const Scene& scene);
// The lights' part of validateScene (the solver checks what it is handed with it).
void validateLights(const Scene& scene);

// A spot's relative intensity at cosTheta (the cosine of the angle from its axis):
// KHR_lights_punctual's smooth falloff, t^2 with t = (cosTheta - cos outer) / (cos inner - cos outer)
// clamped to [0, 1].
double spotFalloff(const Light& spot, double cosTheta);

// The window a directional light's parallel beam covers: the rectangle, normal to its direction,
// that the scene's bounding box projects onto (u, v orthonormal, normal to the direction).
struct ParallelWindow {
  Vec3 u{1.0, 0.0, 0.0}, v{0.0, 1.0, 0.0};
  double a0 = 0.0, a1 = 0.0;  // along u, metres
  double b0 = 0.0, b1 = 0.0;  // along v
  double areaM2() const { return (a1 - a0) * (b1 - b0); }
};
ParallelWindow parallelWindow(const Scene& scene, const Vec3& direction);

// A light's power in watts per channel: point 4 pi I; spot I times the integral of its falloff
// over the sphere, 2 pi I [(1 - cos inner) + (cos inner - cos outer) / 3]; directional E times the
// area of its parallel window (all it sends into the scene's bounding box).
Rgb lightPower(const Scene& scene, const Light& light);

// Total emitted power in watts, summed over RGB: sum of area * (E_r + E_g + E_b), plus the lights'.
double emittedPowerW(const Scene& scene);

}  // namespace radmesh
