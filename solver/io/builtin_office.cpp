#include "solver/io/builtin_office.h"

#include <cmath>
#include <numbers>
#include <string>

#include "solver/io/interior_materials.h"
#include "solver/io/scene_builder.h"

namespace radmesh {

namespace {

// A 7.2 m x 5.4 m x 2.7 m office: x runs east, y north, z up, the floor's south-west corner at
// the origin. A door recess in the west wall, two window recesses in the north wall, six flush
// ceiling light panels; two desks under the windows, an L-shaped corner desk, chairs, two
// bookcases with books, filing cabinets, a round meeting table and a whiteboard. Furniture stands
// on the floor with its bottom faces left out, and keeps clear of the walls (or, where it touches
// one, leaves out the face against it), so that no two surfaces overlap in one plane.
constexpr double kOfficeX = 7.2, kOfficeY = 5.4, kOfficeZ = 2.7;
constexpr double kDeskZ = 0.72, kTopM = 0.03;  // desk height and top thickness

struct OfficeMaterials {
  int wall, ceiling, floor, light, door, frame, glass, oak, beech, fabric, steel, cabinet, board, cork,
      screen;
  int book[4];
};

OfficeMaterials addOfficeMaterials(SceneBuilder& b) {
  OfficeMaterials m{};
  m.wall = b.addMaterial(interior::kWallPaint);
  m.ceiling = b.addMaterial(interior::kCeilingTile);
  m.floor = b.addMaterial(interior::kCarpet);
  m.light = b.addMaterial(interior::kLightPanel);
  m.door = b.addMaterial("door", {0.45, 0.30, 0.18});
  m.frame = b.addMaterial(interior::kDoorFrame);
  m.glass = b.addMaterial("window glass", {0.08, 0.10, 0.12});
  m.oak = b.addMaterial(interior::kOak);
  m.beech = b.addMaterial(interior::kBeech);
  m.fabric = b.addMaterial(interior::kChairFabric);
  m.steel = b.addMaterial("steel", {0.35, 0.35, 0.37});
  m.cabinet = b.addMaterial(interior::kCabinetEnamel);
  m.board = b.addMaterial("whiteboard", {0.85, 0.85, 0.85});
  m.cork = b.addMaterial("cork", {0.50, 0.36, 0.22});
  m.screen = b.addMaterial("monitor", {0.10, 0.10, 0.11});
  m.book[0] = b.addMaterial("red book", {0.55, 0.12, 0.10});
  m.book[1] = b.addMaterial("green book", {0.12, 0.40, 0.18});
  m.book[2] = b.addMaterial("blue book", {0.12, 0.18, 0.50});
  m.book[3] = b.addMaterial("cream book", {0.75, 0.70, 0.55});
  return m;
}

void addShell(SceneBuilder& b, const OfficeMaterials& m) {
  std::vector<Opening> openings;
  openings.push_back({kXMin, {0, 3.9, 0}, {0, 4.8, 2.1}, 0.15, m.frame, m.door, "door"});
  for (double x0 : {1.5, 4.2})
    openings.push_back({kYMax, {x0, 0, 0.9}, {x0 + 1.5, 0, 2.2}, 0.3, m.wall, m.glass, "window"});
  for (double x : {1.2, 3.0, 4.8})
    for (double y : {1.5, 3.6})
      openings.push_back({kZMax, {x, y, 0}, {x + 1.2, y + 0.6, 0}, 0.0, -1, m.light, "light"});
  b.addRoom({0, 0, 0}, {kOfficeX, kOfficeY, kOfficeZ}, {m.floor, m.ceiling, m.wall}, openings, "office");
}

// A chair whose seat is centred at (x, y), its back on `backSide` (kXMin, kXMax, kYMin or kYMax).
void addChair(SceneBuilder& b, const OfficeMaterials& m, double x, double y, Side backSide) {
  const double h = 0.23, leg = 0.04, seatZ = 0.42;
  for (double dx : {-1.0, 1.0})
    for (double dy : {-1.0, 1.0}) {
      const Vec3 c{x + dx * (h - leg), y + dy * (h - leg), 0};
      b.addBox(c - Vec3{leg / 2, leg / 2, 0}, c + Vec3{leg / 2, leg / 2, seatZ}, m.steel, "chair leg",
               kZMin | kZMax);
    }
  b.addBox({x - h, y - h, seatZ}, {x + h, y + h, seatZ + 0.06}, m.fabric, "chair seat");
  Vec3 lo{x - h, y - h, seatZ + 0.06}, hi{x + h, y + h, seatZ + 0.51};
  switch (backSide) {
    case kXMin:
      hi.x = lo.x + 0.05;
      break;
    case kXMax:
      lo.x = hi.x - 0.05;
      break;
    case kYMin:
      hi.y = lo.y + 0.05;
      break;
    default:
      lo.y = hi.y - 0.05;
      break;
  }
  b.addBox(lo, hi, m.fabric, "chair back", kZMin);
}

// A desk x0..x1, y0..y1 on two end panels with a modesty panel on the side `back` (kYMin/kYMax),
// a monitor and a keyboard.
void addDesk(SceneBuilder& b, const OfficeMaterials& m, double x0, double y0, double x1, double y1, Side back) {
  b.addBox({x0, y0, kDeskZ}, {x1, y1, kDeskZ + kTopM}, m.oak, "desk top");
  for (double px : {x0 + 0.02, x1 - 0.05})
    b.addBox({px, y0 + 0.02, 0}, {px + 0.03, y1 - 0.02, kDeskZ}, m.oak, "desk panel", kZMin | kZMax);
  const double py = back == kYMax ? y1 - 0.06 : y0 + 0.04;
  b.addBox({x0 + 0.05, py, 0.3}, {x1 - 0.05, py + 0.02, kDeskZ}, m.oak, "modesty panel",
           kXMin | kXMax | kZMax);
  const double cx = 0.5 * (x0 + x1);
  const double my = back == kYMax ? y1 - 0.45 : y0 + 0.05;  // monitor towards the back
  b.addBox({cx - 0.2, my, kDeskZ + kTopM}, {cx + 0.2, my + 0.4, kDeskZ + kTopM + 0.38}, m.screen, "monitor",
           kZMin);
  const double ky = back == kYMax ? y0 + 0.1 : y1 - 0.25;
  b.addBox({cx - 0.23, ky, kDeskZ + kTopM}, {cx + 0.23, ky + 0.15, kDeskZ + kTopM + 0.03}, m.steel,
           "keyboard", kZMin);
}

// The L-shaped corner desk in the south-east corner: a concave top on three panels.
void addCornerDesk(SceneBuilder& b, const OfficeMaterials& m) {
  const double e = kOfficeX - 0.05, s = 0.05;
  b.addPrism({{5.0, s}, {e, s}, {e, 2.3}, {e - 0.75, 2.3}, {e - 0.75, s + 0.75}, {5.0, s + 0.75}}, kDeskZ,
             kDeskZ + kTopM, m.oak, "corner desk top");
  b.addBox({5.02, s + 0.02, 0}, {5.05, s + 0.73, kDeskZ}, m.oak, "corner desk panel", kZMin | kZMax);
  b.addBox({e - 0.73, 2.25, 0}, {e - 0.02, 2.28, kDeskZ}, m.oak, "corner desk panel", kZMin | kZMax);
  b.addBox({e - 0.05, s + 0.02, 0}, {e - 0.02, s + 0.73, kDeskZ}, m.oak, "corner desk panel", kZMin | kZMax);
  b.addBox({e - 0.55, s + 0.1, kDeskZ + kTopM}, {e - 0.15, s + 0.5, kDeskZ + kTopM + 0.38}, m.screen,
           "monitor", kZMin);
}

// A bookcase against the south wall (a 2 cm gap behind it), x0 .. x0 + 0.9, with books.
void addBookcase(SceneBuilder& b, const OfficeMaterials& m, double x0) {
  const double x1 = x0 + 0.9, y0 = 0.02, y1 = y0 + 0.35, h = 2.0, t = 0.02;
  for (double px : {x0, x1 - t})
    b.addBox({px, y0, 0}, {px + t, y1, h}, m.beech, "bookcase side", kZMin | kZMax);
  b.addBox({x0, y0, h}, {x1, y1, h + t}, m.beech, "bookcase top");
  b.addBox({x0 + t, y0, 0}, {x1 - t, y0 + 0.01, h}, m.beech, "bookcase back", kXMin | kXMax | kZMin | kZMax);
  b.addBox({x0 + t, y0 + 0.01, 0}, {x1 - t, y1, 0.08}, m.beech, "bookcase plinth",
           kXMin | kXMax | kYMin | kZMin);
  // Shelves every 0.38 m above the plinth; books on all but the top one, 4 mm apart.
  static constexpr double kWidth[] = {0.035, 0.05, 0.03, 0.045, 0.06, 0.04, 0.03};
  static constexpr double kHeight[] = {0.24, 0.28, 0.21, 0.26, 0.30, 0.23};
  int k = 0;
  for (int shelf = 0; shelf < 5; ++shelf) {
    const double z = 0.08 + shelf * 0.38;
    if (shelf > 0)
      b.addBox({x0 + t, y0 + 0.01, z - t}, {x1 - t, y1, z}, m.beech, "shelf", kXMin | kXMax | kYMin);
    if (shelf == 4) break;
    for (double x = x0 + t + 0.01; x + 0.06 < x1 - t; ++k) {
      const double w = kWidth[k % 7];
      b.addBox({x, y0 + 0.05, z}, {x + w, y0 + 0.28, z + kHeight[k % 6]}, m.book[k % 4], "book", kZMin);
      x += w + 0.004;
    }
  }
}

// A four-drawer filing cabinet against the west wall (2 cm gap), y0 .. y0 + 0.5.
void addCabinet(SceneBuilder& b, const OfficeMaterials& m, double y0) {
  const double x0 = 0.02, x1 = 0.64, y1 = y0 + 0.5;
  b.addBox({x0, y0, 0}, {x1, y1, 1.32}, m.cabinet, "filing cabinet", kZMin);
  for (int d = 0; d < 4; ++d) {
    const double z = 0.04 + d * 0.32;
    b.addBox({x1, y0 + 0.02, z}, {x1 + 0.02, y1 - 0.02, z + 0.28}, m.cabinet, "drawer front", kXMin);
  }
}

// A low cupboard against the east wall (2 cm gap) with two doors and a printer on it.
void addCredenza(SceneBuilder& b, const OfficeMaterials& m) {
  const double x1 = kOfficeX - 0.02, x0 = x1 - 0.45, y0 = 2.8, y1 = 4.6, h = 0.75;
  b.addBox({x0, y0, 0}, {x1, y1, h}, m.beech, "credenza", kZMin);
  const double mid = 0.5 * (y0 + y1);
  for (auto [d0, d1] : {std::pair{y0 + 0.02, mid - 0.01}, std::pair{mid + 0.01, y1 - 0.02}})
    b.addBox({x0 - 0.02, d0, 0.06}, {x0, d1, h - 0.04}, m.oak, "credenza door", kXMax);
  b.addBox({x0 + 0.03, y0 + 0.2, h}, {x1 - 0.03, y0 + 0.7, h + 0.3}, m.cabinet, "printer", kZMin);
}

std::vector<Vec2> regularPolygon(Vec2 centre, double radius, int sides) {
  std::vector<Vec2> out;
  for (int i = 0; i < sides; ++i) {
    const double a = 2.0 * std::numbers::pi * i / sides;
    out.push_back(centre + radius * Vec2{std::cos(a), std::sin(a)});
  }
  return out;
}

void addRoundTable(SceneBuilder& b, const OfficeMaterials& m, Vec2 c) {
  b.addPrism(regularPolygon(c, 0.55, 16), kDeskZ, kDeskZ + kTopM, m.oak, "round table top");
  b.addPrism(regularPolygon(c, 0.05, 8), 0.04, kDeskZ, m.steel, "round table column", kZMin | kZMax);
  b.addPrism(regularPolygon(c, 0.3, 8), 0.0, 0.04, m.steel, "round table foot", kZMin);
}

}  // namespace

Scene officeScene() {
  SceneBuilder b("office");
  const OfficeMaterials m = addOfficeMaterials(b);
  addShell(b, m);
  // Two desks under the windows, their users facing north.
  for (double x0 : {1.5, 4.2}) {
    addDesk(b, m, x0, 4.55, x0 + 1.5, 5.3, kYMax);
    addChair(b, m, x0 + 0.75, 4.1, kYMin);
  }
  addCornerDesk(b, m);
  addChair(b, m, 6.0, 1.3, kYMax);
  addBookcase(b, m, 0.9);
  addBookcase(b, m, 1.85);
  for (double y0 : {0.5, 1.05, 1.6}) addCabinet(b, m, y0);
  b.addBox({0, 2.25, 0.9}, {0.02, 3.65, 2.1}, m.board, "whiteboard", kXMin);
  b.addBox({3.0, 0, 1.0}, {4.6, 0.015, 1.9}, m.cork, "pin board", kYMin);
  addCredenza(b, m);
  for (Vec2 bin : {Vec2{1.3, 4.95}, Vec2{3.3, 4.95}, Vec2{6.9, 2.6}})
    b.addBox({bin.x - 0.14, bin.y - 0.14, 0}, {bin.x + 0.14, bin.y + 0.14, 0.34}, m.steel, "waste bin",
             kZMin);
  const Vec2 table{3.7, 2.4};
  addRoundTable(b, m, table);
  addChair(b, m, table.x - 0.85, table.y, kXMin);
  addChair(b, m, table.x + 0.85, table.y, kXMax);
  addChair(b, m, table.x, table.y - 0.85, kYMin);
  addChair(b, m, table.x, table.y + 0.85, kYMax);
  return b.take();
}

}  // namespace radmesh
