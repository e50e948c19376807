#pragma once
// The meshing grid turned to follow a building drawn at an angle to the world axes. Architects'
// models are often turned about the vertical (a site plan's north), or have wings at an angle to
// each other; on the world grid such walls would be cut into patches stretched by 1 / cos of the
// angle and floors into slivers along the walls. Each polygon is meshed on the world grid or on one
// of a few turned ones, each turned about one world axis: the one most of its edges lie along.
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

struct GridTurn {
  int axis = 2;          // the world axis the grid is turned about
  double radians = 0.0;  // 0: the world grid itself, bit for bit
  // Then tilted about one of the turned grid's own axes: an outline's own grid only, where its plane
  // is tilted to the grid it lies along (a roof's slope on a building turned in plan).
  int tiltAxis = 0;
  double tiltRadians = 0.0;
  Vec3 pivot{0.0};       // the point the grid turns about: a grid corner, at its polygons' corner
  bool own = false;      // one outline's own grid: it lies along none of the model's grids

  bool turned() const { return radians != 0.0 || tiltRadians != 0.0; }
  bool moved() const { return turned() || pivot != Vec3(0.0); }  // its lines off the world's
  double degrees() const;
  Vec3 toGrid(const Vec3& world) const;
  Vec3 toWorld(const Vec3& grid) const;
  // Directions only turn.
  Vec3 directionToGrid(const Vec3& world) const;
  Vec3 directionToWorld(const Vec3& grid) const;
};

// The grids of a model's polygons (outlines).
struct Grids {
  GridTurn world;               // the world grid: through the origin, or a far model's corner
  std::vector<GridTurn> turns;  // the turned ones, the model's then the outlines' own; not the world's
  std::vector<int> turnOf;      // per outline: an index into turns, or -1 for the world grid
  std::vector<double> edgeM;    // per turn: the length of the edges of its outlines along it
  double worldEdgeM = 0.0;      // the same for the outlines on the world grid

  const GridTurn& of(size_t outline) const;
  size_t outlinesOn(size_t turn) const;  // how many outlines are meshed on turns[turn]
  size_t outlinesOnOwnGrids() const;
  // The turn most of the model's edge length lies along, or none where the world grid's is more.
  GridTurn principal() const;
};

// A turn is a direction about one world axis, modulo a quarter turn, along which (within half a
// degree) lie at least a quarter of all the model's edge length, edges square to the axis; up to
// four of them. An outline goes on the grid (world or turned) whose axes the most of its edge
// length lies along, the world's on a tie, so a model along the axes keeps the world grid. A
// turned grid's lines pass through the corner of its outlines' box in its frame, as the world
// grid's pass through the origin, where models are often drawn from.
// A model far from the origin (site coordinates) has the world grid's lines through the corner of
// its box, as a turned grid's, so that where it sits does not change its mesh.
// An outline that lies along more of a direction of its own (about a world axis) than along the
// grid it would go on gets its own grid, turned to that direction, its lines through its own
// corner: the facets of a curved wall or a round column, a wing too small for a turn of the
// model's, a chair at an angle. On the world grid they would be cut across into slivers.
// So does an outline whose plane is tilted about one axis of the grid it would go on (a roof's
// slope, a ramp), as much along it or more: its grid is tilted with it, so that it lies flat on
// it. On the grid below, its patches would be 1 / cos(pitch) long up the slope.
Grids gridsOf(const Scene& scene);
Grids gridsOf(const std::vector<const std::vector<Vec3>*>& outlines);

// The principal turn (Grids::principal) of a scene or of any outlines (a bake's triangles, the
// viewer's faces).
GridTurn gridTurnOf(const Scene& scene);
GridTurn gridTurnOf(const std::vector<const std::vector<Vec3>*>& outlines);

}  // namespace radmesh
