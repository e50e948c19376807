#pragma once
// What a walkthrough needs to know about a scene's geometry: its bounds, which axis is up, and
// whether one side of it is open (a Cornell box is looked into from its open front).
#include <memory>
#include <vector>

#include "solver/meshing/grid_turn.h"
#include "solver/scene/scene.h"

namespace radmesh {

// A planar face of the geometry (polygon or triangle), counter-clockwise seen from its front.
struct FrameFace {
  std::vector<Vec3> vertices;
};

struct SceneFrame {
  Vec3 boundsMin{0.0};
  Vec3 boundsMax{0.0};
  int upAxis = 2;  // 0 x, 1 y, 2 z
  // A vertical side of the bounds that walls cover less than half of: 2 * axis + (0 for the
  // side at boundsMin, 1 for the side at boundsMax). -1: every side is closed.
  int openSide = -1;
  // Where the furniture is: the area-weighted centre of the faces facing up between the lowest
  // floor and the ceiling (desk tops, seats), and their area; 0 in an empty room.
  Vec3 furnitureCentre{0.0};
  double furnitureAreaM2 = 0.0;
  // The faces it was made from (shared: frames are copied), for freeSpaceAt.
  std::shared_ptr<const std::vector<FrameFace>> faces;
  // The plan's turn about the up axis (the meshing grid's, gridTurnOf): none for a building drawn
  // along the axes.
  GridTurn planTurn;
  double floorLevel() const { return boundsMin[upAxis]; }
  double heightM() const { return boundsMax[upAxis] - boundsMin[upAxis]; }
};

SceneFrame frameOf(std::vector<FrameFace> faces, int upAxis);
// The frame of the same faces turned by the plan's turn back onto the axes (planTurn.toGrid): the
// building as if drawn along them.
SceneFrame alongItsPlan(const SceneFrame& frame);

// Whether an eye at `eye` stands in free space: the nearest face straight above it and straight
// below it shows it its front, and so does the nearest along each direction of the plan, if any (a
// window or a door may open on nothing), none of those nearer than `clearM`. Inside a wall the
// nearest faces show their backs; in a courtyard nothing is above. True without faces.
bool freeSpaceAt(const SceneFrame& frame, const Vec3& eye, double clearM);
// How far the eye sees along the unit `direction` before a face (infinity: none; 0 without faces).
double clearDistance(const SceneFrame& frame, const Vec3& eye, const Vec3& direction);

// A scene's frame, with the scene's up axis.
SceneFrame sceneFrame(const Scene& scene);

}  // namespace radmesh
