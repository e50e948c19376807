#include "solver/io/daylight.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "solver/geometry/openings.h"
#include "solver/geometry/scene_rays.h"
#include "solver/io/mgf_color.h"
#include "solver/scene/scene_error.h"
#include "solver/scene/sun.h"

namespace radmesh {

const char* toString(SkyModel model) { return model == SkyModel::Uniform ? "uniform" : "cie-overcast"; }

SkyModel parseSkyModel(const std::string& text) {
  for (SkyModel m : {SkyModel::Uniform, SkyModel::CieOvercast})
    if (text == toString(m)) return m;
  throw OptionError("--sky-model must be 'uniform' or 'cie-overcast', not '" + text + "'");
}

void checkSkyLux(double lux) {
  if (!(lux >= kDimmestLux && lux <= kSunAboveTheAtmosphereLux))
    throw OptionError(fmt::format("--sky must be the sky's horizontal illuminance in lux, at least {} and at most {}, "
                                  "the sun's above the atmosphere (e.g. 10000, an overcast day), not {}",
                                  kDimmestLux, kSunAboveTheAtmosphereLux, lux));
}

double skyIlluminanceLux(SkyModel model, double horizontalLux, double cosTilt) {
  if (!(cosTilt > -1.0)) return 0.0;  // facing straight down: the black ground alone
  const double c = std::min(cosTilt, 1.0);
  const double pi = std::acos(-1.0);
  // A uniform sky of radiance L over the upper hemisphere, seen by a plane tilted by beta:
  // pi L (1 + cos beta) / 2, with E_h = pi L.
  if (model == SkyModel::Uniform) return horizontalLux * (1.0 + c) / 2.0;
  // CIE overcast: L = Lz/3 + (2 Lz/3) cos(zenith angle), E_h = 7 pi Lz / 9. The first term is a
  // uniform sky; the second integrates max(0, w.z) max(0, w.n) over the sphere, which is
  // (2/3) ((pi - beta) cos beta + sin beta) for unit vectors at angle beta.
  const double lz = 9.0 * horizontalLux / (7.0 * pi);
  const double beta = std::acos(c);
  return std::max(0.0, lz / 3.0 * pi * (1.0 + c) / 2.0 + 4.0 * lz / 9.0 * ((pi - beta) * c + std::sin(beta)));
}

std::vector<std::string> addSkyEmitters(Scene& scene, const Daylight& daylight) {
  const OpeningSearch search = findOpenings(scene);
  const double clearance = 1e-7 * sceneDiagonal(scene);
  NoteTally skipped = search.skipped;
  const SceneRays rays(scene);
  std::vector<Polygon> emitters;
  double areaM2 = 0.0, powerW = 0.0;
  for (const OpeningPolygon& opening : search.openings) {
    const Vec3 out = -glm::normalize(newellNormal(opening.vertices));
    const std::string where = fmt::format("the opening around ({:.4g}, {:.4g}, {:.4g})", opening.inside.x,
                                          opening.inside.y, opening.inside.z);
    // The outside of a model (the rim of a shell standing on no floor) looks out into the model.
    if (rays.hits(opening.inside, out, clearance)) {
      skipped.add("onto the model", where + " looks out onto the model itself, not the sky: no daylight there");
      continue;
    }
    const double lux = skyIlluminanceLux(daylight.sky, daylight.skyLux, glm::dot(out, glm::normalize(daylight.up)));
    if (!(lux > 0.0)) {
      skipped.add("onto the ground", where + " looks down at the ground, which is black: no daylight there");
      continue;
    }
    const Rgb exitance(lux / kWhiteEfficacyLmPerW);  // white light, as MGF's `ed` (scene-formats.md)
    scene.materials.push_back({fmt::format("sky (opening {})", emitters.size() + 1), Rgb(0.0), exitance, true});
    emitters.push_back({opening.vertices, static_cast<int>(scene.materials.size() - 1),
                        fmt::format("sky opening {}", emitters.size() + 1)});
    areaM2 += polygonArea(opening.vertices);
    powerW += polygonArea(opening.vertices) * 3.0 * exitance.r;
  }
  std::vector<std::string> notes = skipped.lines();
  if (emitters.empty()) {
    std::string why;
    for (const std::string& n : notes) why += "; " + n;
    throw SceneError(scene.source, "--sky", "has no opening to let daylight in" + why,
                     "leave a window or skylight open as a hole in its surfaces (docs/scene-formats.md#daylight), "
                     "or give the scene an emitter");
  }
  scene.polygons.insert(scene.polygons.end(), emitters.begin(), emitters.end());
  notes.insert(notes.begin(), fmt::format("daylight: {} sky of {:g} lux through {} opening(s), {:.6g} m^2, "
                                          "{:.6g} W", toString(daylight.sky), daylight.skyLux, emitters.size(),
                                          areaM2, powerW));
  return notes;
}

}  // namespace radmesh
