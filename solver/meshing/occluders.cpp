#include "solver/meshing/occluders.h"

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>
#include <span>

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
// The hierarchy's depth is at most kHeuristicDepth levels, then log2 of the polygons and of a
// polygon's patches, rounded up (together at most 33 for int indices).
constexpr int kHeuristicDepth = 32;
constexpr int kMaxDepth = kHeuristicDepth + 33;

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

Box unite(const Box& a, const Box& b) { return {glm::min(a.lo, b.lo), glm::max(a.hi, b.hi)}; }

// The index of the widest axis of a box.
int widestAxis(const Box& box) {
  const Vec3 extent = box.hi - box.lo;
  return extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
}

double surfaceArea(const Box& box) {
  const Vec3 e = box.hi - box.lo;
  return e.x * e.y + e.y * e.z + e.z * e.x;
}

// Where to split groups_[first, first + count): the surface area heuristic over 16 bins of their box
// centres along each axis, since polygons differ in size by orders of magnitude (a floor beside a
// cup) and a median split would put the floor's box in every node around it. -1: no useful split.
struct GroupSplit {
  int axis = -1;
  double at = 0.0;  // centres (lo + hi) below it go left
};
GroupSplit bestSplit(std::span<const Occluders::Group> groups) {
  constexpr int kBins = 16;
  Box centres{groups[0].box.lo + groups[0].box.hi, groups[0].box.lo + groups[0].box.hi};
  for (const auto& g : groups) centres = unite(centres, Box{g.box.lo + g.box.hi, g.box.lo + g.box.hi});
  GroupSplit best;
  double bestCost = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = centres.lo[axis], width = centres.hi[axis] - lo;
    if (!(width > 0.0)) continue;
    const auto binOf = [&](const Occluders::Group& g) {
      return std::min(kBins - 1, static_cast<int>(kBins * ((g.box.lo[axis] + g.box.hi[axis]) - lo) / width));
    };
    std::array<Box, kBins> boxes;
    std::array<int, kBins> counts{};
    for (const auto& g : groups) {
      const int b = binOf(g);
      boxes[b] = counts[b]++ ? unite(boxes[b], g.box) : g.box;
    }
    std::array<double, kBins> rightCost{};
    Box right;
    int rightCount = 0;
    for (int b = kBins - 1; b > 0; --b) {
      if (counts[b]) right = rightCount ? unite(right, boxes[b]) : boxes[b];
      rightCount += counts[b];
      rightCost[b] = rightCount ? surfaceArea(right) * rightCount : 0.0;
    }
    Box left;
    int leftCount = 0;
    for (int b = 0; b + 1 < kBins; ++b) {
      if (counts[b]) left = leftCount ? unite(left, boxes[b]) : boxes[b];
      leftCount += counts[b];
      if (leftCount == 0 || leftCount == static_cast<int>(groups.size())) continue;
      const double cost = surfaceArea(left) * leftCount + rightCost[b + 1];
      if (cost < bestCost) {
        bestCost = cost;
        best = {axis, lo + width * (b + 1) / kBins};
      }
    }
  }
  return best;
}

}  // namespace

// Each polygon's patches make one subtree, so that a segment skips the polygons it starts and ends
// on whole, rather than visiting every patch box around its two ends.
Occluders::Occluders(const std::vector<Patch>& patches) : patches_(&patches), order_(patches.size()) {
  for (const Patch& p : patches) boxes_.push_back(boxOf(p, 0.0));
  std::iota(order_.begin(), order_.end(), 0);
  std::stable_sort(order_.begin(), order_.end(), [&](int p, int q) { return patches[p].polygon < patches[q].polygon; });
  std::vector<Group> groups;
  for (int i = 0; i < static_cast<int>(order_.size()); ++i) {
    const bool samePolygon = i > 0 && patches[order_[i]].polygon == patches[order_[i - 1]].polygon;
    if (samePolygon) ++groups.back().count;
    else groups.push_back({{}, i, 1});
  }
  for (Group& g : groups) g.box = boxOfPatches(g.first, g.count);
  if (!groups.empty()) buildGroups(groups, 0);
}

Occluders::Box Occluders::boxOfPatches(int first, int count) const {
  Box box = boxes_[order_[first]];
  for (int i = first + 1; i < first + count; ++i) box = unite(box, boxes_[order_[i]]);
  return box;
}

int Occluders::addNode(const Box& box, int first, int count, int polygon) {
  nodes_.push_back({box, first, count, -1, polygon});
  return static_cast<int>(nodes_.size()) - 1;
}

// Splits the groups by bestSplit, depth first: a node's left child follows it. Past kHeuristicDepth
// levels they are halved instead, which bounds the depth (kMaxDepth) where the heuristic would peel
// one polygon off at a time (polygons in a row, each twice the last).
int Occluders::buildGroups(std::span<Group> groups, int depth) {
  const int count = static_cast<int>(groups.size());
  if (count == 1) return buildPatches(groups[0].first, groups[0].count);
  Box box = groups[0].box;
  for (const Group& g : groups) box = unite(box, g.box);
  const int index = addNode(box, 0, 0, -1);
  const auto begin = groups.begin(), end = groups.end();
  const GroupSplit split = depth < kHeuristicDepth ? bestSplit(groups) : GroupSplit{};
  int half = count / 2;
  if (split.axis >= 0) {
    half = static_cast<int>(std::partition(begin, end, [&](const Group& g) {
                              return g.box.lo[split.axis] + g.box.hi[split.axis] < split.at;
                            }) - begin);
  }
  if (half == 0 || half == count) {  // centres all alike: halve them
    half = count / 2;
    std::nth_element(begin, begin + half, end, [](const Group& g, const Group& h) { return g.first < h.first; });
  }
  buildGroups(groups.first(half), depth + 1);
  nodes_[index].right = buildGroups(groups.subspan(half), depth + 1);
  return index;
}

// The same split over one polygon's patches order_[first, first + count).
int Occluders::buildPatches(int first, int count) {
  const Box box = boxOfPatches(first, count);
  const int polygon = (*patches_)[order_[first]].polygon;
  if (count <= kLeafPatches) return addNode(box, first, count, polygon);
  const int index = addNode(box, 0, 0, polygon);
  const int axis = widestAxis(box);
  const auto centre = [&](int p) { return boxes_[p].lo[axis] + boxes_[p].hi[axis]; };
  const int half = count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                   [&](int p, int q) { return centre(p) < centre(q); });
  buildPatches(first, half);
  nodes_[index].right = buildPatches(first + half, count - half);
  return index;
}

bool Occluders::segmentBlocked(const Vec3& a, const Vec3& b, int skipA, int skipB) const {
  if (nodes_.empty()) return false;
  const Box segment{glm::min(a, b), glm::max(a, b)};
  // Far more than the slab test's rounding, so that no box the segment touches is passed over.
  const double margin = 1e-9 * (glm::length(segment.hi - segment.lo) + glm::length(nodes_[0].box.hi - nodes_[0].box.lo) +
                                glm::length(a) + glm::length(b));
  int stack[kMaxDepth + 1];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (node.polygon >= 0 && (node.polygon == skipA || node.polygon == skipB)) continue;
    if (!overlap(segment, node.box) || !segmentMeets(a, b, node.box, margin)) continue;
    if (node.right < 0) {
      for (int i = node.first; i < node.first + node.count; ++i)
        if (overlap(segment, boxes_[order_[i]]) && segmentCrosses(a, b, (*patches_)[order_[i]])) return true;
      continue;
    }
    stack[top++] = node.right;
    stack[top++] = static_cast<int>(&node - nodes_.data()) + 1;
  }
  return false;
}

}  // namespace radmesh
