#pragma once
// What a walkthrough needs to know about a scene's geometry: its bounds, which axis is up, and
// whether one side of it is open (a Cornell box is looked into from its open front).
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

struct SceneFrame {
  Vec3 boundsMin{0.0};
  Vec3 boundsMax{0.0};
  int upAxis = 2;  // 0 x, 1 y, 2 z
  // A vertical side of the bounds that walls cover less than half of: 2 * axis + (0 for the
  // side at boundsMin, 1 for the side at boundsMax). -1: every side is closed.
  int openSide = -1;
  double floorLevel() const { return boundsMin[upAxis]; }
  double heightM() const { return boundsMax[upAxis] - boundsMin[upAxis]; }
};

// A planar face of the geometry (polygon or triangle), counter-clockwise seen from its front.
struct FrameFace {
  std::vector<Vec3> vertices;
  bool givesLight = false;
};

// Scenes arrive z-up (MGF, the built-in office) or y-up (glTF), and nothing in the file says
// which. Ceiling lights decide: up is the axis whose negative direction the most light-giving area
// faces. No downward light: z.
SceneFrame frameOf(const std::vector<FrameFace>& faces);

// A scene's frame: its emitters are the lights.
SceneFrame sceneFrame(const Scene& scene);

}  // namespace radmesh
