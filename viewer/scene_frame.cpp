#include "viewer/scene_frame.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace radmesh {

namespace {

// The vertical side of the bounds least covered by walls along it, if under half. A wall is a
// face turned inward along the side's axis within 10% of the extent of the side's plane: real
// walls are a little off square (the Cornell box's) or stand back from recessed doors and
// windows (the office's, by 0.3 m).
int openSide(const std::vector<FrameFace>& faces, const SceneFrame& frame) {
  const Vec3 extent = frame.boundsMax - frame.boundsMin;
  int best = -1;
  double bestCoverage = 0.5;
  for (int axis = 0; axis < 3; ++axis) {
    if (axis == frame.upAxis) continue;
    const double sideArea = extent[(axis + 1) % 3] * extent[(axis + 2) % 3];
    const double toleranceM = 0.1 * extent[axis];
    for (int end = 0; end < 2; ++end) {
      const double plane = end == 0 ? frame.boundsMin[axis] : frame.boundsMax[axis];
      const double inward = end == 0 ? 1.0 : -1.0;
      double covered = 0.0;
      for (const FrameFace& face : faces) {
        const Vec3 area = 0.5 * newellNormal(face.vertices);
        bool wall = inward * area[axis] >= 0.9 * glm::length(area);
        for (const Vec3& v : face.vertices) wall = wall && std::abs(v[axis] - plane) <= toleranceM;
        if (wall) covered += std::abs(area[axis]);
      }
      const double coverage = sideArea > 0.0 ? covered / sideArea : 1.0;
      if (coverage < bestCoverage) {
        bestCoverage = coverage;
        best = 2 * axis + end;
      }
    }
  }
  return best;
}

}  // namespace

SceneFrame frameOf(const std::vector<FrameFace>& faces, int upAxis) {
  SceneFrame frame;
  frame.upAxis = upAxis;
  if (faces.empty()) return frame;
  frame.boundsMin = Vec3(std::numeric_limits<double>::infinity());
  frame.boundsMax = -frame.boundsMin;
  for (const FrameFace& face : faces)
    for (const Vec3& p : face.vertices) {
      frame.boundsMin = glm::min(frame.boundsMin, p);
      frame.boundsMax = glm::max(frame.boundsMax, p);
    }
  frame.openSide = openSide(faces, frame);
  // A tenth of the height clear of floor and ceiling: a raised floor or a lowered ceiling is no desk.
  const double clearM = 0.1 * frame.heightM();
  Vec3 weighted(0.0);
  for (const FrameFace& face : faces) {
    const Vec3 area = 0.5 * newellNormal(face.vertices);
    bool top = area[upAxis] >= 0.9 * glm::length(area) && area[upAxis] > 0.0;
    Vec3 centre(0.0);
    for (const Vec3& v : face.vertices) {
      top = top && v[upAxis] > frame.boundsMin[upAxis] + clearM && v[upAxis] < frame.boundsMax[upAxis] - clearM;
      centre += v / double(face.vertices.size());
    }
    if (!top) continue;
    weighted += area[upAxis] * centre;
    frame.furnitureAreaM2 += area[upAxis];
  }
  if (frame.furnitureAreaM2 > 0.0) frame.furnitureCentre = weighted / frame.furnitureAreaM2;
  return frame;
}

SceneFrame sceneFrame(const Scene& scene) {
  std::vector<FrameFace> faces;
  faces.reserve(scene.polygons.size());
  for (const Polygon& polygon : scene.polygons)
    faces.push_back({polygon.vertices});
  return frameOf(faces, scene.upAxis);
}

}  // namespace radmesh
