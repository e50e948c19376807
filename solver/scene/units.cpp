#include "solver/scene/units.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "solver/scene/scene_error.h"

namespace radmesh {

namespace {

struct Unit {
  const char* name;
  double metres;
};
constexpr Unit kUnits[] = {{"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}, {"in", 0.0254}, {"ft", 0.3048}};

double largestExtent(const Scene& scene) {
  const auto [low, high] = boundingBox(scene.polygons);
  const Vec3 extent = high - low;
  return std::max({extent.x, extent.y, extent.z});
}

}  // namespace

double parseUnits(const std::string& text) {
  for (const Unit& unit : kUnits)
    if (text == unit.name) return unit.metres;
  throw OptionError("--units '" + text +
                    "' is not a unit: give m, cm, mm, in or ft (what the file's coordinates are in)");
}

std::string implausibleUnitsWarning(const Scene& scene, double metresPerUnit, const std::string& file) {
  const auto plausible = [](double metres) { return metres >= kSmallestModelM && metres <= kLargestModelM; };
  const double across = largestExtent(scene);
  if (plausible(across)) return "";
  const double drawn = across / metresPerUnit;  // in the file's own coordinates
  const Unit* given = std::ranges::find(kUnits, metresPerUnit, &Unit::metres);
  // Of the units that give a plausible size, the one nearest a room's 10 m (by ratio).
  const Unit* best = nullptr;
  for (const Unit& unit : kUnits)
    if (plausible(drawn * unit.metres) &&
        (!best || std::abs(std::log(drawn * unit.metres / 10.0)) < std::abs(std::log(drawn * best->metres / 10.0))))
      best = &unit;
  const std::string fix =
      !best ? "check the file's coordinates: no unit radmesh reads gives it a building's size"
      : best->metres == 1.0
          ? fmt::format("if its coordinates are metres, leave --units out (it is then {:.6g} m across)", drawn)
          : fmt::format("if its coordinates are in {0}, give --units {0} (it is then {1:.6g} m across)", best->name,
                        drawn * best->metres);
  const bool small = across < kSmallestModelM;
  return fmt::format("{}: with --units {} the model is {:.6g} m across, too {} for a building, a room or a "
                     "luminaire ({} {:g} m): {}",
                     file, given != std::end(kUnits) ? given->name : fmt::format("{:g}", metresPerUnit), across,
                     small ? "small" : "large", small ? "under" : "over", small ? kSmallestModelM : kLargestModelM,
                     fix);
}

void scaleScene(Scene& scene, double metresPerUnit) {
  for (Polygon& p : scene.polygons)
    for (Vec3& v : p.vertices) v *= metresPerUnit;
  for (Light& light : scene.lights) light.position *= metresPerUnit;
}

std::string unitsNote(const Scene& scene) {
  constexpr double kLargestBuildingM = 1000.0;
  const double across = largestExtent(scene);
  if (!(across > kLargestBuildingM)) return "";
  return fmt::format("the model is {:.6g} m across, read in metres; if its coordinates are in millimetres, "
                     "centimetres, inches or feet, give --units mm, cm, in or ft (the cell, the eye height and the "
                     "walking pace are in metres)", across);
}

}  // namespace radmesh
