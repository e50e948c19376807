#pragma once
// The meshing grid turned to follow a building drawn at an angle to the world axes. Architects'
// models are often turned about the vertical (a site plan's north); on the world grid their walls
// would be cut into patches stretched by 1 / cos of the angle and their floors into slivers along
// the walls. The grid stays one global grid, only turned about one world axis.
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

struct GridTurn {
  int axis = 2;          // the world axis the grid is turned about
  double radians = 0.0;  // 0: the world grid itself, bit for bit
  Vec3 pivot{0.0};       // the point the grid turns about: a grid corner, at the model's corner

  bool turned() const { return radians != 0.0; }
  double degrees() const;
  Vec3 toGrid(const Vec3& world) const;
  Vec3 toWorld(const Vec3& grid) const;
  // Directions only turn.
  Vec3 directionToGrid(const Vec3& world) const;
  Vec3 directionToWorld(const Vec3& grid) const;
};

// The turn, about one world axis, of most of the length of the scene's edges square to that axis,
// modulo a quarter turn. The world grid where at least half of that length already lies along the
// world axes, where no one direction holds half of it, or where the edges along the turn are less
// than a quarter of all the scene's edge length.
GridTurn gridTurnOf(const Scene& scene);
// The same over any outlines: a bake's triangles, the viewer's faces.
GridTurn gridTurnOf(const std::vector<const std::vector<Vec3>*>& outlines);

}  // namespace radmesh
