#include "solver/io/builtin_building.h"

#include <algorithm>
#include <charconv>

#include "solver/io/interior_materials.h"
#include "solver/io/scene_builder.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

namespace {

// x runs east along the corridors, y north, z up. Walls are 0.2 m thick: every room and corridor
// is its own closed box, and a door is a passage through the wall (reveals on the room's side,
// a hole of the same size in the corridor's face), as in two-rooms. Windows are open passages in
// exterior walls, so light leaves the building through them.
constexpr double kWallM = 0.2, kHeightM = 2.7;
constexpr double kRoomX = 7.2, kRoomY = 5.4;            // each room, the office's size
constexpr double kCorridorM = 2.4;                      // corridor and spine width
constexpr double kCourtyardM = 4.0;                     // between two wings
constexpr double kDoorX = 0.9, kDoorZ = 2.1;            // door opening
constexpr double kWindowX = 1.2, kSillZ = 0.9, kWindowTopZ = 2.1;
constexpr double kWingY = 2 * kRoomY + kCorridorM + 2 * kWallM;

struct Materials {
  RoomMaterials room, corridor;
  int light, frame, oak, steel, beech, fabric, book;
};

Materials addMaterials(SceneBuilder& b) {
  Materials m{};
  const int wall = b.addMaterial(interior::kWallPaint);
  const int ceiling = b.addMaterial(interior::kCeilingTile);
  m.room = {b.addMaterial(interior::kCarpet), ceiling, wall};
  m.corridor = {b.addMaterial("corridor linoleum", {0.45, 0.42, 0.36}), ceiling, wall};
  m.light = b.addMaterial(interior::kLightPanel);
  m.frame = b.addMaterial(interior::kDoorFrame);
  m.oak = b.addMaterial(interior::kOak);
  m.steel = b.addMaterial(interior::kCabinetEnamel);
  m.beech = b.addMaterial(interior::kBeech);
  m.fabric = b.addMaterial(interior::kChairFabric);
  m.book = b.addMaterial("book spines", {0.45, 0.25, 0.20});
  return m;
}

Opening light(double x0, double y0, double x1, double y1, int material) {
  return {kZMax, {x0, y0, 0}, {x1, y1, 0}, 0.0, -1, material, "light"};
}

// A window in the face `side` (its coordinate along the face is ignored), centred at `centre` on
// the face's horizontal axis: an open passage through the wall.
Opening window(Side side, double centre) {
  const bool alongX = side == kYMin || side == kYMax;
  const Vec3 lo = alongX ? Vec3{centre - kWindowX / 2, 0, kSillZ} : Vec3{0, centre - kWindowX / 2, kSillZ};
  const Vec3 hi = alongX ? Vec3{centre + kWindowX / 2, 0, kWindowTopZ} : Vec3{0, centre + kWindowX / 2, kWindowTopZ};
  return {side, lo, hi, kWallM, -1, -1, "window"};
}

// A door in the face `side` starting at `start` along the face: with the reveals through the wall
// (`depth` kWallM) on one side of it, a plain hole (depth 0) on the other.
Opening door(Side side, double start, double depth, int frame) {
  const bool alongX = side == kYMin || side == kYMax;
  const Vec3 lo = alongX ? Vec3{start, 0, 0} : Vec3{0, start, 0};
  const Vec3 hi = alongX ? Vec3{start + kDoorX, 0, kDoorZ} : Vec3{0, start + kDoorX, kDoorZ};
  return {side, lo, hi, depth, frame, -1, "door"};
}

// A room's furniture in its own frame: lx east from its west wall, ly from its window wall
// inwards (north in a south row, south in a north row).
class Furnisher {
 public:
  Furnisher(SceneBuilder& b, const std::string& room, double x0, double windowWallY, bool south)
      : b_(b), room_(room), x0_(x0), wallY_(windowWallY), sign_(south ? 1.0 : -1.0) {}

  void box(double lx0, double ly0, double lx1, double ly1, double z0, double z1, int material,
           const std::string& what, unsigned omit = 0) {
    const double ya = wallY_ + sign_ * ly0, yb = wallY_ + sign_ * ly1;
    b_.addBox({x0_ + lx0, std::min(ya, yb), z0}, {x0_ + lx1, std::max(ya, yb), z1}, material,
              room_ + " " + what, omit);
  }

 private:
  SceneBuilder& b_;
  std::string room_;
  double x0_, wallY_, sign_;
};

// Two desks with chairs under the window, filing cabinets on the east wall, bookcases on the
// west wall and a meeting table: all clear of the door (lx 0.5 .. 1.4 on the far wall), of the
// window's reveals and of each other.
void furnish(Furnisher f, const Materials& m) {
  for (double x0 : {1.6, 4.0}) {
    f.box(x0, 0.6, x0 + 1.6, 1.4, 0.72, 0.75, m.oak, "desk top");
    for (double lx : {x0 + 0.02, x0 + 1.55})
      f.box(lx, 0.62, lx + 0.03, 1.38, 0.0, 0.72, m.oak, "desk panel", kZMin | kZMax);
    f.box(x0 + 0.55, 1.6, x0 + 1.05, 2.1, 0.42, 0.48, m.fabric, "chair seat");
    f.box(x0 + 0.55, 2.05, x0 + 1.05, 2.1, 0.48, 0.95, m.fabric, "chair back", kZMin);
    f.box(x0 + 0.77, 1.82, x0 + 0.83, 1.88, 0.0, 0.42, m.steel, "chair column", kZMin | kZMax);
  }
  for (double ly : {3.7, 4.25}) f.box(kRoomX - 0.62, ly, kRoomX - 0.02, ly + 0.5, 0.0, 1.3, m.steel, "cabinet", kZMin);
  for (double ly : {0.6, 1.55, 2.5}) {
    f.box(0.02, ly, 0.37, ly + 0.9, 0.0, 2.0, m.beech, "bookcase", kZMin);
    for (double z : {0.4, 0.8, 1.2, 1.6})
      f.box(0.37, ly + 0.02, 0.39, ly + 0.88, z, z + 0.3, m.book, "books", kXMin);
  }
  f.box(3.0, 3.4, 5.0, 4.3, 0.72, 0.75, m.oak, "table top");
  f.box(3.95, 3.8, 4.05, 3.9, 0.0, 0.72, m.steel, "table column", kZMin | kZMax);
}

int parseUnits(const std::string& text, const std::string& name) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < 1 || value > kBuildingMaxUnits)
    throw SceneError(name, "", "is not a building size",
                     "write building:COLSxROWS with COLS and ROWS whole numbers from 1 to " +
                         std::to_string(kBuildingMaxUnits) + ", e.g. building:10x10");
  return value;
}

}  // namespace

BuildingLayout parseBuildingName(const std::string& name) {
  const std::string prefix = kBuildingPrefix;
  const std::string size = name.rfind(prefix, 0) == 0 ? name.substr(prefix.size()) : "";
  const auto x = size.find('x');
  if (x == std::string::npos) parseUnits("", name);  // throws, naming the form
  return {parseUnits(size.substr(0, x), name), parseUnits(size.substr(x + 1), name)};
}

std::string buildingRoomName(int col, int row) {
  std::string name = "r";  // appended, not concatenated: GCC 12 sees a false overlap in "r" + ... (-Wrestrict)
  name += std::to_string(row);
  name += "c";
  name += std::to_string(col);
  return name;
}
std::string buildingCorridorName(int wing) { return "corridor " + std::to_string(wing); }

// Wings along y, each a corridor running east with a row of rooms south of it (row 2w) and one
// north of it (row 2w + 1, when there are that many rows), courtyards between wings, and the spine
// corridor along the west end joining the wing corridors through a door each.
Scene buildingScene(const BuildingLayout& layout) {
  SceneBuilder b(kBuildingPrefix + std::to_string(layout.cols) + "x" + std::to_string(layout.rows));
  const Materials m = addMaterials(b);
  const double x0 = kCorridorM + kWallM;  // the wings start east of the spine
  const double length = layout.cols * (kRoomX + kWallM) - kWallM;
  std::vector<Opening> spine;
  double spineEnd = 0.0;
  for (int w = 0; w < layout.wings(); ++w) {
    const double yb = w * (kWingY + kCourtyardM);
    const double c0 = yb + kRoomY + kWallM, c1 = c0 + kCorridorM, mid = 0.5 * (c0 + c1);
    const bool north = 2 * w + 1 < layout.rows;
    std::vector<Opening> corridor{door(kXMin, mid - kDoorX / 2, 0.0, m.frame), window(kXMax, mid)};
    spine.push_back(door(kXMax, mid - kDoorX / 2, kWallM, m.frame));
    spine.push_back(window(kXMin, mid));
    spine.push_back(light(0.9, mid - 0.6, 1.5, mid + 0.6, m.light));
    for (int c = 0; c < layout.cols; ++c) {
      const double rx = x0 + c * (kRoomX + kWallM);
      corridor.push_back(light(rx + 3.0, mid - 0.3, rx + 4.2, mid + 0.3, m.light));
      for (int side = 0; side < (north ? 2 : 1); ++side) {
        const bool south = side == 0;
        const double ry0 = south ? yb : c1 + kWallM, ry1 = ry0 + kRoomY, ymid = 0.5 * (ry0 + ry1);
        const std::string name = buildingRoomName(c, 2 * w + side);
        const Side toCorridor = south ? kYMax : kYMin, outward = south ? kYMin : kYMax;
        corridor.push_back(door(outward, rx + 0.5, 0.0, m.frame));  // the corridor's face towards the room
        std::vector<Opening> room{door(toCorridor, rx + 0.5, kWallM, m.frame), window(outward, rx + 2.4),
                                  window(outward, rx + 4.8)};
        for (double lx : {1.2, 3.0, 4.8}) room.push_back(light(rx + lx, ymid - 0.3, rx + lx + 1.2, ymid + 0.3, m.light));
        if (c == layout.cols - 1) room.push_back(window(kXMax, ymid));
        b.addRoom({rx, ry0, 0}, {rx + kRoomX, ry1, kHeightM}, m.room, room, name);
        furnish(Furnisher(b, name, rx, south ? ry0 : ry1, south), m);
      }
    }
    b.addRoom({x0, c0, 0}, {x0 + length, c1, kHeightM}, m.corridor, corridor, buildingCorridorName(w));
    spineEnd = north ? c1 + kWallM + kRoomY : c1;
  }
  b.addRoom({0, 0, 0}, {kCorridorM, spineEnd, kHeightM}, m.corridor, spine, kBuildingSpineName);
  return b.take();
}

}  // namespace radmesh
