#include "viewer/cell_visibility.h"

#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <deque>

namespace radmesh {

namespace {

// A cell's free space reaches a voxel (0.15 m) past its walls' faces at most; an eye standing in
// a doorway's reveal is in the free space of one side or the other, so a margin this wide holds it.
constexpr double kEyeMarginM = 0.3;

// A rectangle of normalised device coordinates, [-1, 1] across the screen.
struct ScreenRect {
  glm::dvec2 min{1.0}, max{-1.0};  // empty
  bool empty() const { return min.x >= max.x || min.y >= max.y; }
  bool contains(const ScreenRect& r) const {
    return r.empty() || (min.x <= r.min.x && min.y <= r.min.y && max.x >= r.max.x && max.y >= r.max.y);
  }
};

const ScreenRect kWholeScreen{glm::dvec2(-1.0), glm::dvec2(1.0)};

ScreenRect intersect(const ScreenRect& a, const ScreenRect& b) { return {glm::max(a.min, b.min), glm::min(a.max, b.max)}; }
ScreenRect unite(const ScreenRect& a, const ScreenRect& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return {glm::min(a.min, b.min), glm::max(a.max, b.max)};
}

// The portal's screen rectangle: the whole screen when any corner is behind the eye (its
// projection is not bounded by its corners'), nothing when it lies wholly outside one clip plane.
ScreenRect screenRect(const Portal& portal, const glm::mat4& viewProjection) {
  ScreenRect r;
  bool behind = false;
  std::array<int, 6> outside{};  // corners beyond each clip plane: -x, +x, -y, +y, near, far
  for (const Vec3& v : portal.vertices) {
    const glm::dvec4 c = glm::dmat4(viewProjection) * glm::dvec4(v, 1.0);
    outside[0] += c.x < -c.w, outside[1] += c.x > c.w, outside[2] += c.y < -c.w, outside[3] += c.y > c.w;
    outside[4] += c.z < -c.w, outside[5] += c.z > c.w;
    if (c.w <= 1e-9) {
      behind = true;
      continue;
    }
    const glm::dvec2 ndc(c.x / c.w, c.y / c.w);
    r = unite(r, {ndc, ndc + glm::dvec2(1e-12)});
  }
  const int corners = static_cast<int>(portal.vertices.size());
  for (int n : outside)
    if (n == corners) return {};
  return behind ? kWholeScreen : intersect(r, kWholeScreen);
}

bool holds(const Cell& cell, const Vec3& eye) {
  return glm::all(glm::greaterThanEqual(eye, cell.boundsMin - kEyeMarginM)) &&
         glm::all(glm::lessThanEqual(eye, cell.boundsMax + kEyeMarginM));
}

}  // namespace

std::vector<bool> visibleCells(const CellPartition& partition, const glm::mat4& viewProjection, const Vec3& eye) {
  const size_t n = partition.cells.size();
  std::vector<ScreenRect> seenThrough(n);  // the union of the rectangles each cell is seen through
  std::deque<int> queue;
  for (size_t c = 0; c < n; ++c)
    if (holds(partition.cells[c], eye)) seenThrough[c] = kWholeScreen, queue.push_back(static_cast<int>(c));
  if (queue.empty()) return {};
  std::vector<std::vector<int>> portalsOf(n);
  for (size_t p = 0; p < partition.portals.size(); ++p) {
    portalsOf[partition.portals[p].cellA].push_back(static_cast<int>(p));
    portalsOf[partition.portals[p].cellB].push_back(static_cast<int>(p));
  }
  std::vector<ScreenRect> portalRect(partition.portals.size());
  for (size_t p = 0; p < partition.portals.size(); ++p) portalRect[p] = screenRect(partition.portals[p], viewProjection);
  // A cell is visited again when it is seen through more of the screen than before: the
  // rectangles only grow, so this ends.
  for (; !queue.empty(); queue.pop_front()) {
    const int cell = queue.front();
    for (int p : portalsOf[cell]) {
      const Portal& portal = partition.portals[p];
      const int beyond = portal.cellA == cell ? portal.cellB : portal.cellA;
      const ScreenRect through = intersect(seenThrough[cell], portalRect[p]);
      if (through.empty() || seenThrough[beyond].contains(through)) continue;
      seenThrough[beyond] = unite(seenThrough[beyond], through);
      queue.push_back(beyond);
    }
  }
  std::vector<bool> visible(n);
  for (size_t c = 0; c < n; ++c) visible[c] = !seenThrough[c].empty();
  return visible;
}

}  // namespace radmesh
