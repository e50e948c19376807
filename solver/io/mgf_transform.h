#pragma once
// MGF transforms (the xf entity and the transform arguments of i): rigid motions with uniform
// scale and mirrors, and arrays of them.
#include <string>
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

struct MgfAffine {
  glm::dmat3 linear{1.0};  // rotation x uniform scale x mirrors
  Vec3 offset{0.0};

  Vec3 point(const Vec3& p) const { return linear * p + offset; }
  // True when the transform turns right-handed into left-handed: faces are then reversed so that
  // the right-hand rule still gives the side MGF meant.
  bool mirrors() const { return glm::determinant(linear) < 0.0; }
  // `next` applied after this one.
  MgfAffine then(const MgfAffine& next) const {
    return {next.linear * linear, next.linear * offset + next.offset};
  }
};

// More instances than this (one xf's arrays, or all nested arrays together) are refused rather
// than allowed to exhaust memory.
inline constexpr size_t kMaxMgfInstances = 100000;

// Reads transform arguments -t dx dy dz, -rx/-ry/-rz degrees (counter-clockwise looking toward
// the origin along the axis), -s factor, -mx/-my/-mz, -i N (repeat the arguments that follow N
// times) and -a N (an array: the arguments that follow applied 0, 1, ..., N-1 times). Arguments
// act on the object in the order given; the arguments after -i or -a run up to the next -i or -a.
// Returns one transform per array instance (one when there is no -a). Throws MgfError.
std::vector<MgfAffine> mgfTransformInstances(const std::vector<std::string>& args);

}  // namespace radmesh
