#pragma once
// The scene: planar polygons in metres with diffuse materials. What importers produce and the
// mesher consumes; nothing here knows about patches or light transport.
#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace radmesh {

using Vec3 = glm::dvec3;
using Rgb = glm::dvec3;  // linear RGB, one value per channel

// What a reflectance of 1 or more is lowered to, in every reader: rho = 1 would never let light
// die out, and exporters write 1 for white.
inline constexpr double kHighestReflectance = 0.99;

struct Material {
  std::string name;
  Rgb rho{0.0};        // diffuse reflectance per channel, each in [0, 1)
  Rgb emittance{0.0};  // radiant exitance, W/m^2 per channel
  bool emits() const { return emittance.r > 0.0 || emittance.g > 0.0 || emittance.b > 0.0; }
};

struct Polygon {
  std::vector<Vec3> vertices;  // metres; counter-clockwise seen from the front (lit) side
  int material = 0;            // index into Scene::materials
  std::string origin;          // where it came from, for messages: "line 120: f", "mesh 'desk'"
};

struct Scene {
  std::string source;  // file path or built-in name, for messages
  std::vector<Material> materials;
  std::vector<Polygon> polygons;
  // 0 x, 1 y, 2 z: glTF's y as it defines, the built-in rooms' z; MGF's, which it does not say, and
  // --up's are set by loadScene (solver/io/scene_loader.h, solver/scene/up_axis.h).
  int upAxis = 2;
};

// Newell's normal: its length is twice the polygon's area, robust for non-convex polygons.
Vec3 newellNormal(const std::vector<Vec3>& vertices);
double polygonArea(const std::vector<Vec3>& vertices);

// Throws SceneError for input that cannot be solved: no polygons, NaN or infinite coordinates,
// fewer than 3 vertices, zero area, non-planar polygons, rho outside [0,1), negative or non-finite
// emittance, a material index out of range, or no emitter at all.
void validateScene(const Scene& scene);

// Total emitted power in watts, summed over RGB: sum of area * (E_r + E_g + E_b).
double emittedPowerW(const Scene& scene);

}  // namespace radmesh
