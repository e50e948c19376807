#pragma once
// Exact visibility between two points: the patches as occluders, in a bounding volume hierarchy over
// their boxes (built once per solve), so that a segment tests the few patches near it rather than
// every one. Each scene polygon's patches form one subtree, which a segment from or to that polygon
// passes over whole; the polygons are split by the surface area heuristic. The shadow criterion of
// adaptive subdivision and the receivers too small for a pixel centre ask it.
#include <span>
#include <vector>

#include "solver/meshing/patch.h"

namespace radmesh {

struct AxisBox {
  Vec3 lo{0.0}, hi{0.0};
};

// The box of a patch's vertices, grown by `margin` on every side.
AxisBox boxOf(const Patch& p, double margin);
bool overlap(const AxisBox& a, const AxisBox& b);

// Whether the segment from a to b crosses the plane of patch p strictly, at a point inside it.
bool segmentCrosses(const Vec3& a, const Vec3& b, const Patch& p);

class Occluders {
 public:
  explicit Occluders(const std::vector<Patch>& patches);
  // Whether the segment from a to b passes through a patch other than those of the scene polygons
  // `skipA` and `skipB` (the surfaces it starts and ends on). The same answer as testing every
  // patch: a node is passed over only where the segment misses its box by more than rounding.
  bool segmentBlocked(const Vec3& a, const Vec3& b, int skipA, int skipB) const;

  using Box = AxisBox;
  struct Group {  // one scene polygon's patches, order_[first, first + count)
    Box box;
    int first = 0, count = 0;
  };

 private:
  struct Node {
    Box box;
    int first = 0, count = 0;  // a leaf: patches order_[first, first + count)
    int right = -1;            // an inner node: its children are the next node and `right`
    int polygon = -1;          // the scene polygon all its patches belong to; -1: several
  };
  int buildGroups(std::span<Group> groups, int depth);
  int buildPatches(int first, int count);
  int addNode(const Box& box, int first, int count, int polygon);
  Box boxOfPatches(int first, int count) const;  // of order_[first, first + count)
  const std::vector<Patch>* patches_;
  std::vector<Box> boxes_;  // per patch
  std::vector<int> order_;  // patch indices, each polygon's together
  std::vector<Node> nodes_;
};

}  // namespace radmesh
