#pragma once
// Building scenes in code: rectangles, boxes, prisms and rooms with openings, each emitted as
// planar polygons that face the right way (boxes outward, rooms inward). The built-in scenes are
// made of these.
#include <string>
#include <vector>

#include "solver/geometry/polygon_2d.h"
#include "solver/scene/scene.h"

namespace radmesh {

// The six faces of an axis-aligned box or room, as bits so that a set of them can be left out.
enum Side : unsigned {
  kXMin = 1u << 0,
  kXMax = 1u << 1,
  kYMin = 1u << 2,
  kYMax = 1u << 3,
  kZMin = 1u << 4,  // floor, or a box's bottom
  kZMax = 1u << 5,  // ceiling, or a box's top
};

// A hole in one face of a room, optionally with a recess behind it (a door or window reveal).
struct Opening {
  Side side = kXMin;
  Vec3 lo{0.0}, hi{0.0};    // the hole's corners; the coordinate along the face's normal is ignored
  double depthM = 0.0;      // how far the recess goes behind the face (0: no reveals)
  int revealMaterial = -1;  // the recess's four sides; -1: the face's own material
  int backMaterial = -1;    // closes the recess at its depth (a door, a pane, a light); -1: open
  std::string name;
};

struct RoomMaterials {
  int floor = 0;
  int ceiling = 0;
  int walls = 0;
};

class SceneBuilder {
 public:
  explicit SceneBuilder(std::string source);

  int addMaterial(std::string name, Rgb rho, Rgb emittance = Rgb(0.0));
  int addMaterial(const Material& m) { return addMaterial(m.name, m.rho, m.emittance); }
  void addPolygon(std::vector<Vec3> ccw, int material, std::string origin);

  // The rectangle lo..hi in the plane coordinate[axis] = lo[axis], facing +axis (facing > 0) or
  // -axis, with `holes` (rectangles inside it, not overlapping) left out. The rest is cut into
  // as few rectangles as horizontal bands allow, each one polygon.
  void addRect(int axis, int facing, Vec3 lo, Vec3 hi, int material, const std::string& name,
               const std::vector<std::pair<Vec3, Vec3>>& holes = {});

  // A box lo..hi facing outward; `omit` leaves out faces that rest on or against something (a
  // bottom on the floor), so that no two faces overlap in one plane.
  void addBox(Vec3 lo, Vec3 hi, int material, const std::string& name, unsigned omit = 0);

  // A vertical prism: the counter-clockwise footprint (x, y) from z0 to z1, facing outward.
  // `omit` may hold kZMin and kZMax.
  void addPrism(const std::vector<Vec2>& footprint, double z0, double z1, int material,
                const std::string& name, unsigned omit = 0);

  // A closed room lo..hi seen from inside, with openings in its faces.
  void addRoom(Vec3 lo, Vec3 hi, RoomMaterials materials, const std::vector<Opening>& openings,
               const std::string& name);

  Scene take() { return std::move(scene_); }

 private:
  void addRecess(const Opening& opening, double plane, int faceMaterial, const std::string& name);

  Scene scene_;
};

}  // namespace radmesh
