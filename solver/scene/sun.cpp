#include "solver/scene/sun.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <numbers>
#include <vector>

#include "solver/scene/scene_error.h"

namespace radmesh {

Compass sceneCompass() { return {}; }

Light sunLight(double azimuthDeg, double elevationDeg, double lux, const Compass& compass) {
  if (!(elevationDeg > 0.0 && elevationDeg <= 90.0))
    throw OptionError(fmt::format("--sun elevation {} is {}: give an elevation in degrees from just above 0 to 90 (90: "
                                  "overhead; past it, turn the azimuth by 180 instead)",
                                  elevationDeg, elevationDeg > 90.0 ? "past overhead" : "not above the horizon"));
  if (!std::isfinite(azimuthDeg))
    throw OptionError("--sun azimuth must be a number of degrees clockwise from north (0 north, 90 east)");
  if (!(lux >= kDimmestLux && lux <= kSunAboveTheAtmosphereLux))
    throw OptionError(fmt::format("--sun illuminance {} lux must be at least {} and at most {}, the sun's above the "
                                  "atmosphere: e.g. {} for clear-sky direct sun",
                                  lux, kDimmestLux, kSunAboveTheAtmosphereLux, kClearSkySunLux));
  const double azimuth = std::fmod(azimuthDeg, 360.0) * std::numbers::pi / 180.0;  // 1e308 degrees is a direction too
  const double elevation = elevationDeg * std::numbers::pi / 180.0;
  const Vec3 east = glm::cross(compass.north, compass.up);
  const Vec3 towardSun = std::cos(elevation) * (std::cos(azimuth) * compass.north + std::sin(azimuth) * east) +
                         std::sin(elevation) * compass.up;
  Light sun;
  sun.name = fmt::format("--sun {},{},{}", azimuthDeg, elevationDeg, lux);
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(-towardSun);
  sun.intensity = Rgb(lux / kWhiteEfficacyLmPerW);
  return sun;
}

Light parseSun(const std::string& text, const Compass& compass) {
  std::vector<double> values;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find(',', start), text.size());
    double value = 0.0;
    const char* first = text.data() + start;
    const char* last = text.data() + end;
    const auto [stop, error] = std::from_chars(first, last, value);
    if (first == last || error != std::errc() || stop != last)
      throw OptionError(fmt::format("--sun '{}': '{}' is not a number; give AZIMUTH,ELEVATION[,LUX] in degrees (and "
                                    "lux), e.g. --sun 180,45 or --sun 180,45,80000", text, text.substr(start, end - start)));
    values.push_back(value);
    start = end + 1;
  }
  if (values.size() != 2 && values.size() != 3)
    throw OptionError(fmt::format("--sun '{}' has {} numbers; give AZIMUTH,ELEVATION[,LUX], e.g. --sun 180,45",
                                  text, values.size()));
  return sunLight(values[0], values[1], values.size() == 3 ? values[2] : kClearSkySunLux, compass);
}

}  // namespace radmesh
