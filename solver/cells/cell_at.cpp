#include "solver/cells/cell_at.h"

#include <glm/geometric.hpp>
#include <limits>

namespace radmesh {

namespace {

// Whether the vertical line through `point` crosses the convex patch: `point` on the inner side
// of every edge, seen along the patch's normal (its vertices run counter-clockwise around it).
bool overPatch(const Patch& patch, const Vec3& point, const Vec3& up) {
  const double side = glm::dot(patch.normal, up) > 0.0 ? 1.0 : -1.0;
  for (int k = 0; k < patch.vertexCount; ++k) {
    const Vec3& a = patch.vertices[k];
    const Vec3& b = patch.vertices[(k + 1) % patch.vertexCount];
    if (side * glm::dot(glm::cross(b - a, point - a), up) < 0.0) return false;
  }
  return true;
}

}  // namespace

int cellBelow(const std::vector<Patch>& patches, const CellPartition& partition, const Vec3& point, const Vec3& up) {
  int best = -1;
  double bestDrop = std::numeric_limits<double>::infinity();
  for (size_t j = 0; j < patches.size(); ++j) {
    const Patch& p = patches[j];
    const double facing = glm::dot(p.normal, up);
    if (facing == 0.0) continue;  // a wall: no line along up crosses it
    const double drop = glm::dot(point - p.vertices[0], p.normal) / facing;  // along -up to the plane
    if (drop > 0.0 && drop < bestDrop && overPatch(p, point, up)) {
      bestDrop = drop;
      best = static_cast<int>(j);
    }
  }
  // Above a ceiling's back (on the roof) the eye is outside.
  if (best < 0 || static_cast<size_t>(best) >= partition.cellOfPatch.size() || glm::dot(patches[best].normal, up) < 0.0)
    return kOutsideCell;
  return partition.cellOfPatch[best];
}

int nearestCell(const CellPartition& partition, const Vec3& point) {
  int best = kOutsideCell;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (size_t c = 0; c < partition.cells.size(); ++c) {
    const Cell& cell = partition.cells[c];
    const double distance = glm::length(point - glm::clamp(point, cell.boundsMin, cell.boundsMax));
    if (distance < bestDistance) {
      bestDistance = distance;
      best = static_cast<int>(c);
    }
  }
  return best;
}

}  // namespace radmesh
