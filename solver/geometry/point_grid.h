#pragma once
// Points hashed into cubic buckets of one size, looked up by box: the welding of coincident corners
// (buckets the size of the tolerance) and the search for points on patch edges (buckets the size
// of an edge) in solver/bake/display_radiosity.cpp; the elements sharing an edge
// across polygons in solver/radiosity/adaptive_split.cpp; and, by their boxes, the faces an open
// edge may lie on in solver/geometry/openings.cpp.
#include <cmath>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

class PointGrid {
 public:
  explicit PointGrid(double bucketM) : bucket_(bucketM) {}

  void insert(const Vec3& position, int item) { buckets_[keyOf(position)].push_back(item); }
  // An item with an extent (a face's box) goes in every bucket its box meets.
  void insert(const Vec3& lo, const Vec3& hi, int item) {
    const Key a = keyOf(lo), b = keyOf(hi);
    for (std::int64_t x = a.x; x <= b.x; ++x)
      for (std::int64_t y = a.y; y <= b.y; ++y)
        for (std::int64_t z = a.z; z <= b.z; ++z) buckets_[Key{x, y, z}].push_back(item);
  }

  // Calls visit(item) for the items of every bucket that meets the box lo..hi, until it returns true.
  // Returns whether one did.
  template <class Visit>
  bool anyInBox(const Vec3& lo, const Vec3& hi, Visit&& visit) const {
    const Key a = keyOf(lo), b = keyOf(hi);
    for (std::int64_t x = a.x; x <= b.x; ++x)
      for (std::int64_t y = a.y; y <= b.y; ++y)
        for (std::int64_t z = a.z; z <= b.z; ++z) {
          const auto found = buckets_.find(Key{x, y, z});
          if (found == buckets_.end()) continue;
          for (int item : found->second)
            if (visit(item)) return true;
        }
    return false;
  }

 private:
  struct Key {
    std::int64_t x, y, z;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    size_t operator()(const Key& k) const {
      // Unsigned: the mixing is meant to wrap around.
      const auto u = [](std::int64_t x) { return static_cast<std::uint64_t>(x); };
      return std::hash<std::uint64_t>()(u(k.x) * 73856093u ^ u(k.y) * 19349663u ^ u(k.z) * 83492791u);
    }
  };
  Key keyOf(const Vec3& p) const {
    const Vec3 q = glm::floor(p / bucket_);
    return {static_cast<std::int64_t>(q.x), static_cast<std::int64_t>(q.y), static_cast<std::int64_t>(q.z)};
  }

  double bucket_;
  std::unordered_map<Key, std::vector<int>, KeyHash> buckets_;
};

}  // namespace radmesh
