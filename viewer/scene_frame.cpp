#include "viewer/scene_frame.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "solver/scene/up_axis.h"

namespace radmesh {

namespace {

// The vertical side of the bounds least covered by walls facing in from it, if under half. A wall
// is a face turned inward along the side's axis, wherever it stands: real walls are a little off
// square (the Cornell box's), stand back from recessed doors and windows (the office's, by 0.3 m),
// or close an L-shaped building's notch far from the side of its bounds. Each covers its area
// projected on the side, and faces up to 60 degrees off the axis count: the facets of a round
// room's wall cover its side, where only those within 26 degrees covered 44 % of it.
int openSide(const std::vector<FrameFace>& faces, const SceneFrame& frame) {
  const Vec3 extent = frame.boundsMax - frame.boundsMin;
  int best = -1;
  double bestCoverage = 0.5;
  for (int axis = 0; axis < 3; ++axis) {
    if (axis == frame.upAxis) continue;
    const double sideArea = extent[(axis + 1) % 3] * extent[(axis + 2) % 3];
    for (int end = 0; end < 2; ++end) {
      const double inward = end == 0 ? 1.0 : -1.0;
      double covered = 0.0;
      for (const FrameFace& face : faces) {
        const Vec3 area = 0.5 * newellNormal(face.vertices);
        if (inward * area[axis] >= 0.5 * glm::length(area)) covered += std::abs(area[axis]);
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

SceneFrame frameOf(std::vector<FrameFace> faceList, int upAxis) {
  SceneFrame frame;
  frame.upAxis = upAxis;
  if (faceList.empty()) return frame;
  frame.faces = std::make_shared<const std::vector<FrameFace>>(std::move(faceList));
  const std::vector<FrameFace>& faces = *frame.faces;
  frame.boundsMin = Vec3(std::numeric_limits<double>::infinity());
  frame.boundsMax = -frame.boundsMin;
  for (const FrameFace& face : faces)
    for (const Vec3& p : face.vertices) {
      frame.boundsMin = glm::min(frame.boundsMin, p);
      frame.boundsMax = glm::max(frame.boundsMax, p);
    }
  frame.openSide = openSide(faces, frame);
  std::vector<const std::vector<Vec3>*> outlines;
  for (const FrameFace& face : faces) outlines.push_back(&face.vertices);
  const GridTurn turn = gridTurnOf(outlines);
  if (turn.axis == upAxis) frame.planTurn = turn;
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

SceneFrame alongItsPlan(const SceneFrame& frame) {
  if (!frame.faces) return frame;
  std::vector<FrameFace> faces = *frame.faces;
  for (FrameFace& face : faces)
    for (Vec3& v : face.vertices) v = frame.planTurn.toGrid(v);
  SceneFrame along = frameOf(std::move(faces), frame.upAxis);
  along.planTurn = {};  // along its plan by construction: the camera placed in it turns no further
  return along;
}

namespace {

// The nearest face the ray from `origin` along the unit `direction` crosses: its distance, and
// whether it shows the origin its front. Infinity where it crosses none.
std::pair<double, bool> nearestFace(const std::vector<FrameFace>& faces, const Vec3& origin, const Vec3& direction) {
  std::pair<double, bool> nearest{std::numeric_limits<double>::infinity(), false};
  for (const FrameFace& face : faces) {
    const Vec3 n = newellNormal(face.vertices);
    const double along = glm::dot(n, direction);
    if (along == 0.0) continue;
    const double t = glm::dot(n, face.vertices[0] - origin) / along;
    if (!(t > 0.0 && t < nearest.first)) continue;
    // Is the crossing inside the polygon? Even-odd, in the plane of its two minor axes.
    const Vec3 q = origin + t * direction;
    const Vec3 m = glm::abs(n);
    const int drop = m.x >= m.y && m.x >= m.z ? 0 : m.y >= m.z ? 1 : 2;
    const int a = (drop + 1) % 3, b = (drop + 2) % 3;
    bool in = false;
    for (size_t i = 0, j = face.vertices.size() - 1; i < face.vertices.size(); j = i++) {
      const Vec3& p = face.vertices[i];
      const Vec3& r = face.vertices[j];
      if ((p[b] > q[b]) != (r[b] > q[b]) && q[a] < (r[a] - p[a]) * (q[b] - p[b]) / (r[b] - p[b]) + p[a]) in = !in;
    }
    if (in) nearest = {t, along < 0.0};
  }
  return nearest;
}

}  // namespace

bool freeSpaceAt(const SceneFrame& frame, const Vec3& eye, double clearM) {
  if (!frame.faces) return true;
  const UpFrame axes = upFrame(frame.upAxis);
  for (const Vec3& direction : {axes.up, -axes.up})
    if (!nearestFace(*frame.faces, eye, direction).second) return false;
  for (const Vec3& direction : {axes.across, -axes.across, axes.along, -axes.along}) {
    const auto [distance, front] = nearestFace(*frame.faces, eye, direction);
    if (std::isfinite(distance) && (!front || distance < clearM)) return false;  // none: an opening
  }
  return true;
}

double clearDistance(const SceneFrame& frame, const Vec3& eye, const Vec3& direction) {
  return frame.faces ? nearestFace(*frame.faces, eye, direction).first : 0.0;
}

SceneFrame sceneFrame(const Scene& scene) {
  std::vector<FrameFace> faces;
  faces.reserve(scene.polygons.size());
  for (const Polygon& polygon : scene.polygons)
    faces.push_back({polygon.vertices});
  return frameOf(std::move(faces), scene.upAxis);
}

}  // namespace radmesh
