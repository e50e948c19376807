#include "solver/scene/units.h"

#include <fmt/format.h>

#include <algorithm>

#include "solver/scene/scene_error.h"

namespace radmesh {

double parseUnits(const std::string& text) {
  if (text == "m") return 1.0;
  if (text == "cm") return 0.01;
  if (text == "mm") return 0.001;
  if (text == "in") return 0.0254;
  if (text == "ft") return 0.3048;
  throw OptionError("--units '" + text +
                    "' is not a unit: give m, cm, mm, in or ft (what the file's coordinates are in)");
}

void scaleScene(Scene& scene, double metresPerUnit) {
  for (Polygon& p : scene.polygons)
    for (Vec3& v : p.vertices) v *= metresPerUnit;
  for (Light& light : scene.lights) light.position *= metresPerUnit;
}

std::string unitsNote(const Scene& scene) {
  constexpr double kLargestBuildingM = 1000.0;
  const auto [low, high] = boundingBox(scene.polygons);
  const Vec3 extent = high - low;
  const double across = std::max({extent.x, extent.y, extent.z});
  if (!(across > kLargestBuildingM)) return "";
  return fmt::format("the model is {:.6g} m across, read in metres; if its coordinates are in millimetres, "
                     "centimetres, inches or feet, give --units mm, cm, in or ft (the cell, the eye height and the "
                     "walking pace are in metres)", across);
}

}  // namespace radmesh
