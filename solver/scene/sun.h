#pragma once
// The sun as a directional light (--sun AZIMUTH,ELEVATION[,LUX]): parallel light of a given
// illuminance normal to its direction, placed by azimuth and elevation.
#include <string>

#include "solver/scene/scene.h"

namespace radmesh {

// Clear-sky direct sun at a high elevation, in lux on a surface facing it.
inline constexpr double kClearSkySunLux = 100000.0;
// The sun outside the atmosphere: no daylight on the ground is brighter, so a larger --sun or
// --sky is a typo (1e308 was taken, and balanced a ledger of 1e305 W).
inline constexpr double kSunAboveTheAtmosphereLux = 133000.0;
// A hundredth of starlight's 1e-4 lux: a dimmer --sun or --sky is a typo too (1e-40 lux gave
// emitters too faint for the bake's floats, refused in words about MGF and glTF units).
inline constexpr double kDimmestLux = 1e-6;

// Which way is up and which is north in a scene. One place, so that an up-axis option can change it.
struct Compass {
  Vec3 up{0.0, 0.0, 1.0};
  Vec3 north{0.0, 1.0, 0.0};
};
Compass sceneCompass();  // z up, y north

// The sun at azimuth (degrees clockwise from north, seen from above) and elevation (degrees above
// the horizon) giving `lux` on a surface facing it: irradiance lux / kWhiteEfficacyLmPerW W/m^2
// per channel (white). Throws OptionError naming --sun for an elevation outside (0, 90], a
// non-finite azimuth, or a lux outside [kDimmestLux, kSunAboveTheAtmosphereLux].
Light sunLight(double azimuthDeg, double elevationDeg, double lux, const Compass& compass = sceneCompass());

// "AZIMUTH,ELEVATION[,LUX]" (LUX defaults to kClearSkySunLux). Throws OptionError naming --sun.
Light parseSun(const std::string& text, const Compass& compass = sceneCompass());

}  // namespace radmesh
