#include "solver/formfactors/occluders.h"

#include <algorithm>
#include <numeric>

namespace radmesh {

using Box = AxisBox;

Box boxOf(const Patch& p, double margin) {
  Box b{p.vertices[0], p.vertices[0]};
  for (int k = 1; k < p.vertexCount; ++k) {
    b.lo = glm::min(b.lo, p.vertices[k]);
    b.hi = glm::max(b.hi, p.vertices[k]);
  }
  b.lo -= Vec3(margin);
  b.hi += Vec3(margin);
  return b;
}

bool overlap(const Box& a, const Box& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
         b.lo.z <= a.hi.z;
}

bool segmentCrosses(const Vec3& a, const Vec3& b, const Patch& p) {
  const double da = glm::dot(p.normal, a - p.vertices[0]), db = glm::dot(p.normal, b - p.vertices[0]);
  if (!((da > 0.0 && db < 0.0) || (da < 0.0 && db > 0.0))) return false;
  const Vec3 x = a + (da / (da - db)) * (b - a);
  for (int k = 0; k < p.vertexCount; ++k) {
    const Vec3& v = p.vertices[k];
    if (glm::dot(glm::cross(p.vertices[(k + 1) % p.vertexCount] - v, x - v), p.normal) < 0.0) return false;
  }
  return true;
}

namespace {

constexpr int kLeafPatches = 4;

// Whether the segment a + t (b - a), t in [0, 1], meets the box grown by `margin` (slabs).
bool segmentMeets(const Vec3& a, const Vec3& b, const Box& box, double margin) {
  double enter = 0.0, leave = 1.0;
  for (int k = 0; k < 3; ++k) {
    const double lo = box.lo[k] - margin, hi = box.hi[k] + margin, d = b[k] - a[k];
    if (d == 0.0) {
      if (a[k] < lo || a[k] > hi) return false;
      continue;
    }
    const double t0 = (lo - a[k]) / d, t1 = (hi - a[k]) / d;
    enter = std::max(enter, std::min(t0, t1));
    leave = std::min(leave, std::max(t0, t1));
    if (enter > leave) return false;
  }
  return true;
}

}  // namespace

Occluders::Occluders(const std::vector<Patch>& patches) : patches_(&patches), order_(patches.size()) {
  for (const Patch& p : patches) boxes_.push_back(boxOf(p, 0.0));
  std::iota(order_.begin(), order_.end(), 0);
  if (!patches.empty()) build(0, static_cast<int>(patches.size()));
}

// Median split along the box centres' widest axis, depth first: a node's left child follows it.
int Occluders::build(int first, int count) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back({boxes_[order_[first]], first, count, -1});
  Box box = boxes_[order_[first]];
  for (int i = first; i < first + count; ++i) {
    box.lo = glm::min(box.lo, boxes_[order_[i]].lo);
    box.hi = glm::max(box.hi, boxes_[order_[i]].hi);
  }
  nodes_[index].box = box;
  if (count <= kLeafPatches) return index;
  const Vec3 extent = box.hi - box.lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  const auto centre = [&](int p) { return boxes_[p].lo[axis] + boxes_[p].hi[axis]; };
  const int half = count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                   [&](int p, int q) { return centre(p) < centre(q); });
  build(first, half);
  const int right = build(first + half, count - half);
  nodes_[index].count = 0;
  nodes_[index].right = right;
  return index;
}

bool Occluders::segmentBlocked(const Vec3& a, const Vec3& b, int skipA, int skipB) const {
  if (nodes_.empty()) return false;
  const Box segment{glm::min(a, b), glm::max(a, b)};
  // Far more than the slab test's rounding, so that no box the segment touches is passed over.
  const double margin = 1e-9 * (glm::length(segment.hi - segment.lo) + glm::length(nodes_[0].box.hi - nodes_[0].box.lo) +
                                glm::length(a) + glm::length(b));
  int stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!overlap(segment, node.box) || !segmentMeets(a, b, node.box, margin)) continue;
    if (node.right < 0) {
      for (int i = node.first; i < node.first + node.count; ++i) {
        const Patch& p = (*patches_)[order_[i]];
        if (p.polygon == skipA || p.polygon == skipB) continue;
        if (overlap(segment, boxes_[order_[i]]) && segmentCrosses(a, b, p)) return true;
      }
      continue;
    }
    stack[top++] = node.right;
    stack[top++] = static_cast<int>(&node - nodes_.data()) + 1;
  }
  return false;
}

}  // namespace radmesh
