#include "solver/scene/up_axis.h"

#include <algorithm>

#include "solver/scene/scene_error.h"

namespace radmesh {

UpChoice parseUpChoice(const std::string& text) {
  if (text == "x") return UpChoice::X;
  if (text == "y") return UpChoice::Y;
  if (text == "z") return UpChoice::Z;
  if (text == "auto") return UpChoice::Auto;
  throw OptionError("--up '" + text + "' is not an axis: give x, y, z, or auto (decided from the geometry)");
}

const char* upAxisName(int axis) { return axis == 0 ? "x" : axis == 1 ? "y" : "z"; }

UpFrame upFrame(int axis) {
  if (axis == 0) return {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}};
  if (axis == 1) return {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}};
  return {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
}

Vec3 rotateToYUp(const Vec3& p, int upAxis) {
  const UpFrame from = upFrame(upAxis), to = upFrame(1);
  return glm::dot(p, from.across) * to.across + glm::dot(p, from.along) * to.along + glm::dot(p, from.up) * to.up;
}

int guessUpAxis(const Scene& scene) {
  const auto [low, high] = boundingBox(scene.polygons);
  const Vec3 extent = high - low;
  Vec3 floorArea(0.0), downwardLight(0.0);
  double light = 0.0, total = 0.0;
  for (const Polygon& p : scene.polygons) {
    const Vec3 area = 0.5 * newellNormal(p.vertices);
    const double size = glm::length(area);
    const bool emits = scene.materials.at(static_cast<size_t>(p.material)).emits();
    total += size;
    if (emits) light += size;
    for (int axis = 0; axis < 3; ++axis) {
      if (emits && -area[axis] >= 0.95 * size) downwardLight[axis] += size;
      const bool lowest = std::all_of(p.vertices.begin(), p.vertices.end(),
                                      [&](const Vec3& v) { return v[axis] <= low[axis] + 0.1 * extent[axis]; });
      if (area[axis] >= 0.95 * size && lowest) floorArea[axis] += size;
    }
  }
  Vec3 score(0.0);
  for (int axis = 0; axis < 3; ++axis) {
    const double crossSection = extent[(axis + 1) % 3] * extent[(axis + 2) % 3];
    // A floor is a sizeable part of what stands on it: not the end cap of a lone luminaire.
    if (crossSection > 0.0 && floorArea[axis] >= 0.05 * total) score[axis] += floorArea[axis] / crossSection;
    if (light > 0.0) score[axis] += downwardLight[axis] / light;
  }
  int up = 2;  // ties keep z, then y
  for (int axis : {1, 0})
    if (score[axis] > score[up] * (1.0 + 1e-9)) up = axis;
  return up;
}

std::string applyUpChoice(Scene& scene, UpChoice choice) {
  switch (choice) {
    case UpChoice::Format: return {};
    case UpChoice::X: scene.upAxis = 0; return {};
    case UpChoice::Y: scene.upAxis = 1; return {};
    case UpChoice::Z: scene.upAxis = 2; return {};
    case UpChoice::Auto: break;
  }
  scene.upAxis = guessUpAxis(scene);
  return std::string("--up auto: ") + upAxisName(scene.upAxis) +
         " is up (the axis along which the floor faces up at the bottom and the lights face down)";
}

}  // namespace radmesh
