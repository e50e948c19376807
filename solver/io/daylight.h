#pragma once
// Daylight: a sky that lights a scene through its openings (docs/scene-formats.md#daylight).
#include <string>
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

// Uniform: the same luminance everywhere. CIE overcast (CIE S 011 standard sky 1): three times as
// bright at the zenith as at the horizon, L = Lz (1 + 2 sin(elevation)) / 3.
enum class SkyModel { Uniform, CieOvercast };
const char* toString(SkyModel model);            // "uniform", "cie-overcast"
SkyModel parseSkyModel(const std::string& text);  // throws OptionError

// Throws OptionError unless `lux` is a finite illuminance above 0 (--sky's value).
void checkSkyLux(double lux);

struct Daylight {
  double skyLux = 0.0;  // horizontal illuminance of the unobstructed sky; 0: no sky
  SkyModel sky = SkyModel::Uniform;
  Vec3 up{0.0, 0.0, 1.0};
  std::vector<Light> sun{};  // --sun: the sun's directional light, joining the scene's own lights

};

// Illuminance (lux) from the sky above the horizon on a plane whose normal is at cos(tilt)
// `cosTilt` to the zenith (1: facing up, 0: vertical), the ground black; closed forms.
double skyIlluminanceLux(SkyModel model, double horizontalLux, double cosTilt);

// Puts a diffuse emitter (rho 0, its own material "sky (opening K)") in every opening of the scene
// that looks out at the sky, facing in, with the exitance of the illuminance its opening receives.
// Returns what it did, a line per opening it passed over and why. Throws SceneError when no
// opening lets daylight in.
std::vector<std::string> addSkyEmitters(Scene& scene, const Daylight& daylight);

}  // namespace radmesh
