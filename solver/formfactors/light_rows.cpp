#include "solver/formfactors/light_rows.h"

#include <algorithm>
#include <limits>
#include <optional>

#include "solver/projection/environment_projection.h"
#include "solver/projection/hemicube.h"
#include "solver/projection/projection.h"

namespace radmesh {

namespace {

// A directional light's window in its viewpoint's frame: centred on the origin.
ProjectionFace parallelFace(const ParallelWindow& w, int resolution) {
  ProjectionFace face;
  face.parallel = true;
  face.a1 = 0.5 * (w.a1 - w.a0);
  face.a0 = -face.a1;
  face.b1 = 0.5 * (w.b1 - w.b0);
  face.b0 = -face.b1;
  face.width = face.height = resolution;
  return face;
}

}  // namespace

ProjectionSurface lightSurface(const Scene& scene, const Light& light, int resolution) {
  ProjectionSurface surface;
  if (light.type == LightType::Directional) {
    // Every pixel of the window carries the same irradiance times the same area.
    addFace(surface, parallelFace(parallelWindow(scene, light.direction), resolution),
            [](double, double, double) { return 1.0; });
  } else {
    const bool point = light.type == LightType::Point;
    for (const ProjectionFace& face : point ? cubeFaces(resolution) : hemicubeFaces(resolution))
      addFace(surface, face, [&](double a, double b, double pixelArea) {
        const Vec3 d = face.toLocal({a, b});
        const double r = glm::length(d);
        const double solidAngle = pixelArea / (r * r * r);  // dA cos(theta) / r^2, cos(theta) = 1 / r
        return point ? solidAngle : solidAngle * spotFalloff(light, d.z / r);
      });
    surface.wholeSphere = point;
  }
  scaleToCapturedFraction(surface, 1.0);  // all the light's power leaves through its surface
  return surface;
}

Patch lightViewpoint(const Scene& scene, const Light& light, const std::vector<Patch>& patches) {
  Patch viewpoint;
  if (light.type != LightType::Directional) {
    const Vec3 n = light.type == LightType::Spot ? light.direction : Vec3(0.0, 0.0, 1.0);
    const auto [u, v] = perpendicularAxes(n);
    viewpoint.frame = {u, v, n};
    viewpoint.centroid = light.position;
    return viewpoint;
  }
  const ParallelWindow w = parallelWindow(scene, light.direction);
  const Vec3& n = light.direction;
  double nearest = std::numeric_limits<double>::max();
  for (const Patch& p : patches)
    for (int k = 0; k < p.vertexCount; ++k) nearest = std::min(nearest, glm::dot(p.vertices[k], n));
  // Behind every patch by the window's size, so that depths are of the scene's scale.
  const double setBack = std::max(w.a1 - w.a0, w.b1 - w.b0);
  viewpoint.frame = {w.u, w.v, n};
  viewpoint.centroid = 0.5 * (w.a0 + w.a1) * w.u + 0.5 * (w.b0 + w.b1) * w.v + (nearest - setBack) * n;
  return viewpoint;
}

LightRows::LightRows(const Scene& scene, const std::vector<Patch>& patches, int resolution, double nearDepth,
                     ThreadPool& pool)
    : scene_(scene), patches_(patches), resolution_(resolution), nearDepth_(nearDepth), pool_(pool) {
  // The sky in a window is no surface to a light: it shines through onto what lies behind.
  for (size_t j = 0; j < patches.size(); ++j)
    if (!scene.materials.at(patches[j].material).skyOpening) solid_.push_back(static_cast<int>(j));
  if (solid_.size() != patches.size())
    for (int j : solid_) solidPatches_.push_back(patches[j]);
}

FormFactorRow LightRows::row(const Light& light) {
  const bool all = solid_.size() == patches_.size();
  const std::vector<Patch>& projected = all ? patches_ : solidPatches_;
  std::optional<EnvironmentProjection> own;
  const bool point = light.type == LightType::Point;
  std::optional<EnvironmentProjection>& projection = point ? points_ : own;
  if (!projection) projection.emplace(projected, lightSurface(scene_, light, resolution_), nearDepth_, pool_);
  projection->projectFrom(lightViewpoint(scene_, light, patches_), -1);
  FormFactorRow row = assembleRow(-1, 1.0, projection->pixelFormFactors(), projection->seenFromFront());
  if (!all)
    for (int& receiver : row.receivers) receiver = solid_[receiver];  // ascending still
  return row;
}

FormFactorRow lightRow(const Scene& scene, const Light& light, const std::vector<Patch>& patches, int resolution,
                       double nearDepth, ThreadPool& pool) {
  return LightRows(scene, patches, resolution, nearDepth, pool).row(light);
}

double lightsPowerOutside(const Scene& scene, const std::vector<Patch>& patches, int resolution, ThreadPool& pool) {
  LightRows rows(scene, patches, resolution, sceneNearDepth(patches), pool);
  double outside = 0.0;
  for (const Light& light : scene.lights) {
    const Rgb power = lightPower(scene, light);
    if (!(channelSum(power) > 0.0)) continue;  // as a solve: a dark light, or a beam with no window
    outside += channelSum(power) * rows.row(light).outsideFraction();
  }
  return outside;
}

}  // namespace radmesh
