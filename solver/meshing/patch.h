#pragma once
// A patch: the unit of radiosity (the paper's section 1.6). Convex, planar, within one grid cell.
#include <array>
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

// Orthonormal frame of a patch's projection surface: n is the patch normal, u and v span the
// single plane above it.
struct Frame {
  Vec3 u{1, 0, 0};
  Vec3 v{0, 1, 0};
  Vec3 n{0, 0, 1};
};

struct Patch {
  std::array<Vec3, 4> vertices{};  // counter-clockwise around normal; vertexCount of them used
  int vertexCount = 0;             // 3 (triangle) or 4 (convex quad)
  Vec3 centroid{0.0};              // area centroid
  Vec3 normal{0, 0, 1};            // unit
  double areaM2 = 0.0;
  Frame frame;
  int material = 0;  // index into Scene::materials
  int polygon = 0;   // index into Scene::polygons
};

}  // namespace radmesh
