#include "solver/radiosity/effects_plan.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include <fmt/format.h>

#include "solver/formfactors/near_field.h"

namespace radmesh {

namespace {

double sceneExtent(const Scene& scene) {
  Vec3 lo(INFINITY), hi(-INFINITY);
  for (const Polygon& p : scene.polygons)
    for (const Vec3& v : p.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
  return glm::length(hi - lo);
}

bool grey(const Rgb& c) { return c.r == c.g && c.g == c.b; }

// An edge's supporting line, canonical up to sign and rounded to a tolerance, so that collinear
// edges of different polygons fall into one bucket.
using LineKey = std::tuple<long long, long long, long long, long long, long long, long long>;

LineKey lineKey(const Vec3& a, const Vec3& b, double tolerance) {
  Vec3 d = glm::normalize(b - a);
  if (d.x < 0 || (d.x == 0 && (d.y < 0 || (d.y == 0 && d.z < 0)))) d = -d;
  const Vec3 foot = a - glm::dot(a, d) * d;  // the line's point nearest the origin
  auto q = [](double x, double step) { return static_cast<long long>(std::llround(x / step)); };
  return {q(d.x, 1e-6), q(d.y, 1e-6), q(d.z, 1e-6), q(foot.x, tolerance), q(foot.y, tolerance), q(foot.z, tolerance)};
}

}  // namespace

bool isConvexEnclosure(const Scene& scene) {
  const double tolerance = 1e-9 * sceneExtent(scene);
  for (const Polygon& p : scene.polygons) {
    const Vec3 n = glm::normalize(newellNormal(p.vertices));
    const Vec3 origin = p.vertices[0];
    for (const Polygon& q : scene.polygons)
      for (const Vec3& v : q.vertices)
        if (glm::dot(v - origin, n) < -tolerance) return false;
  }
  return true;
}

bool isClosed(const Scene& scene) {
  struct Edge {
    Vec3 a, b;
    size_t polygon;
  };
  const double tolerance = 1e-7 * sceneExtent(scene);
  std::map<LineKey, std::vector<Edge>> lines;
  for (size_t i = 0; i < scene.polygons.size(); ++i) {
    const auto& v = scene.polygons[i].vertices;
    for (size_t k = 0; k < v.size(); ++k) {
      const Vec3 a = v[k], b = v[(k + 1) % v.size()];
      if (glm::length(b - a) > tolerance) lines[lineKey(a, b, tolerance)].push_back({a, b, i});
    }
  }
  // Every edge must be covered along its whole length by edges of other polygons.
  for (const auto& [key, edges] : lines) {
    for (const Edge& e : edges) {
      const Vec3 d = glm::normalize(e.b - e.a);
      const double length = glm::length(e.b - e.a);
      std::vector<std::pair<double, double>> cover;
      for (const Edge& f : edges) {
        if (f.polygon == e.polygon) continue;
        double s = glm::dot(f.a - e.a, d), t = glm::dot(f.b - e.a, d);
        if (s > t) std::swap(s, t);
        cover.emplace_back(s, t);
      }
      std::sort(cover.begin(), cover.end());
      double reached = 0.0;
      for (const auto& [s, t] : cover) {
        if (s > reached + tolerance) break;
        reached = std::max(reached, t);
      }
      if (reached < length - tolerance) return false;
    }
  }
  return true;
}

EffectsPlan planEffects(const Scene& scene, const std::vector<Patch>& patches, EffectsMode mode) {
  const bool forceAll = mode == EffectsMode::All;
  EffectsPlan plan;
  const bool convex = isConvexEnclosure(scene);
  plan.occlusion = !convex;
  const std::string occlusionWhy =
      convex ? "the scene is a convex enclosure: no patch can hide another, analytic form factors are exact"
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

  const bool closed = isClosed(scene);
  plan.escape = !closed;
  const std::string escapeWhy = closed ? "the surface is closed: no light can leave the scene"
                                       : "the surface has open edges: light leaving through openings is accounted";

  plan.nearReceivers = findNearFieldReceivers(patches);
  size_t pairs = 0, shooters = 0;
  for (const auto& near : plan.nearReceivers) pairs += near.size(), shooters += !near.empty();
  plan.nearField = pairs > 0;
  const std::string nearWhy =
      pairs > 0 ? fmt::format("{} shooter-receiver pairs, from {} of the {} patches, are closer than the shooter's "
                              "size: area-to-area form factors for those pairs only",
                              pairs, shooters, patches.size())
                : "no receiver is closer to a shooter than the shooter's size: point-source form factors hold";

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
