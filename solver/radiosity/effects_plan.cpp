#include "solver/radiosity/effects_plan.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include <fmt/format.h>

#include "solver/formfactors/near_field.h"
#include "solver/geometry/openings.h"
#include "solver/geometry/scene_rays.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

namespace {

bool grey(const Rgb& c) { return c.r == c.g && c.g == c.b; }

struct Closure {
  size_t openStretches = 0;  // edges no other edge or face closes
  bool closed = true;        // no light can leave
};

Closure closure(const Scene& scene) {
  const std::vector<BoundarySegment> open = boundarySegments(scene, 1e-7 * sceneDiagonal(scene));
  return {open.size(), !lightCanLeave(scene, open)};
}

}  // namespace

bool isConvexEnclosure(const Scene& scene) {
  const double tolerance = 1e-9 * sceneDiagonal(scene);
  // The vertices about a point among them, so that a normal's rounding weighs by the scene's size.
  const Vec3 centre = scene.polygons.empty() ? Vec3(0.0) : scene.polygons[0].vertices[0];
  std::vector<Vec3> points;
  double radius = 0.0;
  for (const Polygon& p : scene.polygons)
    for (const Vec3& v : p.vertices) {
      points.push_back(v - centre);
      radius = std::max(radius, glm::length(points.back()));
    }
  const auto lowest = [&](const Vec3& n) {
    double low = std::numeric_limits<double>::infinity();
    for (const Vec3& v : points) low = std::min(low, glm::dot(v, n));
    return low;
  };
  // Every vertex on or in front of every polygon's plane. A wall exported as thousands of polygons
  // has one plane: the lowest vertex along it is found once per normal (to 1e-9), and bounds a
  // polygon whose normal n differs from that by d to within |d| times the scene's radius; only a
  // polygon the bound cannot clear is measured itself. Else a finely meshed box took n^2.
  std::map<std::array<long long, 3>, std::pair<Vec3, double>> lowestAlong;
  for (const Polygon& p : scene.polygons) {
    const Vec3 n = glm::normalize(newellNormal(p.vertices));
    const std::array<long long, 3> key = {std::llround(n.x * 1e9), std::llround(n.y * 1e9), std::llround(n.z * 1e9)};
    auto [at, added] = lowestAlong.try_emplace(key);
    if (added) at->second = {n, lowest(n)};
    const auto& [along, low] = at->second;
    const double offset = glm::dot(p.vertices[0] - centre, n);
    if (low - glm::length(n - along) * radius - offset >= -tolerance) continue;
    if (lowest(n) - offset < -tolerance) return false;
  }
  return true;
}

void checkAnalyticSeesNoShadows(const Scene& scene, Projection projection) {
  if (projection != Projection::Analytic || isConvexEnclosure(scene)) return;
  throw OptionError(fmt::format("--projection analytic has no visibility, and {} is not a convex enclosure: its "
                                "patches can hide one another, and their shadows would be lit; use --projection "
                                "hemicube (or plane), which resolve occlusion",
                                scene.source));
}

bool isClosed(const Scene& scene) { return closure(scene).closed; }

EffectsPlan planEffects(const Scene& scene, const std::vector<Patch>& patches, EffectsMode mode) {
  const bool forceAll = mode == EffectsMode::All;
  EffectsPlan plan;
  const bool convex = isConvexEnclosure(scene);
  plan.occlusion = !convex;
  const std::string occlusionWhy =
      convex ? "the scene is a convex enclosure: no patch can hide another, so analytic form factors need no visibility"
             : "some polygon has scene geometry behind its plane, so patches can hide one another";

  const bool allGrey = std::all_of(scene.materials.begin(), scene.materials.end(),
                                   [](const Material& m) { return grey(m.rho) && grey(m.emittance); }) &&
                       std::all_of(scene.lights.begin(), scene.lights.end(),
                                   [](const Light& l) { return grey(l.intensity); });
  plan.colour = !allGrey;
  const std::string colourWhy = allGrey ? "every material and emitter is grey: one channel stands for three"
                                        : "some material or emitter has colour: three channels";

  const bool black = std::all_of(scene.materials.begin(), scene.materials.end(),
                                 [](const Material& m) { return m.rho == Rgb(0.0); });
  plan.interreflection = !black;
  const std::string interreflectionWhy = black ? "every reflectance is zero: direct light only, one shot per emitter"
                                               : "some surface reflects: light bounces";

  const auto [openStretches, closed] = closure(scene);
  plan.closed = closed;
  plan.escape = !closed;
  const std::string closedAround =
      openStretches == 0 ? "the surface is closed"
                         : fmt::format("the surface is closed around the {} open edges it has (no ray from them or "
                                       "from a face leaves the scene)",
                                       openStretches);
  const std::string escapeWhy =
      !closed ? (openStretches > 0 ? "the surface has open edges: light leaving through openings is accounted"
                                   : "some face looks out of the model: light leaving it is accounted")
              : closedAround + ": no light can leave the scene (what slips through seams between patches by "
                               "rounding is still booked as escaped)";

  plan.nearReceivers = findNearFieldReceivers(patches);
  size_t pairs = 0, shooters = 0;
  for (const auto& near : plan.nearReceivers) pairs += near.size(), shooters += !near.empty();
  plan.nearField = pairs > 0;
  const std::string nearWhy =
      pairs > 0 ? fmt::format("{} shooter-receiver pairs, from {} of the {} patches, are closer than the shooter's "
                              "size or face it across a narrow gap: area-to-area form factors for those pairs only",
                              pairs, shooters, patches.size())
                : "no receiver is closer to a shooter than the shooter's size, nor faces it across a narrow gap: "
                  "point-source form factors hold";

  if (forceAll) plan.occlusion = plan.colour = plan.interreflection = plan.escape = plan.nearField = true;
  auto reason = [&](bool skippable, const std::string& why) {
    return forceAll && skippable ? "forced by --effects all (" + why + ")" : why;
  };
  plan.effects = {{"occlusion", plan.occlusion, reason(convex, occlusionWhy)},
                  {"colour", plan.colour, reason(allGrey, colourWhy)},
                  {"interreflection", plan.interreflection, reason(black, interreflectionWhy)},
                  {"near field", plan.nearField, reason(pairs == 0, nearWhy)},
                  {"escape", plan.escape, reason(closed, escapeWhy)}};
  return plan;
}

}  // namespace radmesh
