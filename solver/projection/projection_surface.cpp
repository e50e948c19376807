#include "solver/projection/projection_surface.h"

#include <map>
#include <mutex>

namespace radmesh {

std::shared_ptr<const ProjectionSurface> sharedSurface(const std::string& key,
                                                       const std::function<ProjectionSurface()>& make) {
  static std::mutex mutex;
  static std::map<std::string, std::weak_ptr<const ProjectionSurface>> made;
  const std::lock_guard<std::mutex> lock(mutex);
  std::shared_ptr<const ProjectionSurface> surface = made[key].lock();
  if (!surface) {
    surface = std::make_shared<const ProjectionSurface>(make());
    made[key] = surface;
  }
  return surface;
}

void addFace(ProjectionSurface& surface, const ProjectionFace& face, const DeltaFormFactorFn& df) {
  const double pixelArea = face.pixelWidth() * face.pixelHeight();
  std::vector<double> table(static_cast<size_t>(face.width) * face.height);
  for (int row = 0; row < face.height; ++row)
    for (int column = 0; column < face.width; ++column) {
      const glm::dvec2 c = face.pixelCentre(column, row);
      table[static_cast<size_t>(row) * face.width + column] = df(c.x, c.y, pixelArea);
    }
  surface.faces.push_back(face);
  surface.deltaFormFactors.push_back(std::move(table));
}

void scaleToCapturedFraction(ProjectionSurface& surface, double capturedFraction) {
  double sum = 0.0;
  for (const auto& table : surface.deltaFormFactors)
    for (double df : table) sum += df;
  surface.tableSum = sum;
  surface.capturedFraction = capturedFraction;
  for (auto& table : surface.deltaFormFactors)
    for (double& df : table) df *= capturedFraction / sum;
}

std::optional<LocalPolygon> inSurfaceView(const ProjectionSurface& surface, const Patch& shooter, const Patch& patch) {
  if (surface.wholeSphere) return toShooterFrame(shooter, patch);
  return inShooterView(shooter, patch);
}

}  // namespace radmesh
