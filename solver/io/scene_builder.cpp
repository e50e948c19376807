#include "solver/io/scene_builder.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace radmesh {

namespace {

// In-plane axes of a face perpendicular to `axis`, in increasing order.
int firstInPlane(int axis) { return axis == 0 ? 1 : 0; }
int secondInPlane(int axis) { return axis == 2 ? 1 : 2; }

struct Rect2 {
  double s0, s1, t0, t1;
};

// The outer rectangle minus the holes, as horizontal bands (cut at every hole's top and bottom)
// split at the holes; a band with the same columns as the one below it extends that one instead.
std::vector<Rect2> minusHoles(const Rect2& outer, const std::vector<Rect2>& holes) {
  std::vector<double> cuts{outer.t0, outer.t1};
  for (const Rect2& h : holes) {
    if (h.s0 < outer.s0 || h.s1 > outer.s1 || h.t0 < outer.t0 || h.t1 > outer.t1 || h.s0 >= h.s1 ||
        h.t0 >= h.t1)
      throw std::logic_error("scene builder: an opening lies outside its face or is empty");
    cuts.push_back(h.t0);
    cuts.push_back(h.t1);
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());

  std::vector<Rect2> out;
  std::vector<std::pair<double, double>> previous;  // columns of the band below
  size_t previousFirst = 0;                         // its rectangles in `out`
  for (size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double t0 = cuts[k], t1 = cuts[k + 1];
    std::vector<Rect2> across;
    for (const Rect2& h : holes)
      if (h.t0 <= t0 && h.t1 >= t1) across.push_back(h);
    std::sort(across.begin(), across.end(), [](const Rect2& a, const Rect2& b) { return a.s0 < b.s0; });
    std::vector<std::pair<double, double>> columns;
    double s = outer.s0;
    for (const Rect2& h : across) {
      if (h.s0 < s) throw std::logic_error("scene builder: openings overlap");
      if (h.s0 > s) columns.emplace_back(s, h.s0);
      s = h.s1;
    }
    if (outer.s1 > s) columns.emplace_back(s, outer.s1);
    if (!columns.empty() && columns == previous) {
      for (size_t i = previousFirst; i < out.size(); ++i) out[i].t1 = t1;
      continue;
    }
    previousFirst = out.size();
    for (const auto& [c0, c1] : columns) out.push_back({c0, c1, t0, t1});
    previous = std::move(columns);
  }
  return out;
}

}  // namespace

SceneBuilder::SceneBuilder(std::string source) { scene_.source = std::move(source); }

int SceneBuilder::addMaterial(std::string name, Rgb rho, Rgb emittance) {
  scene_.materials.push_back({std::move(name), rho, emittance});
  return static_cast<int>(scene_.materials.size()) - 1;
}

void SceneBuilder::addPolygon(std::vector<Vec3> ccw, int material, std::string origin) {
  scene_.polygons.push_back({std::move(ccw), material, std::move(origin)});
}

void SceneBuilder::addRect(int axis, int facing, Vec3 lo, Vec3 hi, int material, const std::string& name,
                           const std::vector<std::pair<Vec3, Vec3>>& holes) {
  const int s = firstInPlane(axis), t = secondInPlane(axis);
  std::vector<Rect2> holes2;
  for (const auto& [a, b] : holes) holes2.push_back({a[s], b[s], a[t], b[t]});
  // (s0,t0) (s1,t0) (s1,t1) (s0,t1) runs counter-clockwise around e_s x e_t, which is -y for
  // the y axis and +axis otherwise.
  const bool reverse = facing * (axis == 1 ? -1 : 1) < 0;
  for (const Rect2& r : minusHoles({lo[s], hi[s], lo[t], hi[t]}, holes2)) {
    std::vector<Vec3> corners;
    for (const auto& [cs, ct] : {std::pair{r.s0, r.t0}, {r.s1, r.t0}, {r.s1, r.t1}, {r.s0, r.t1}}) {
      Vec3 p;
      p[axis] = lo[axis];
      p[s] = cs;
      p[t] = ct;
      corners.push_back(p);
    }
    if (reverse) std::reverse(corners.begin(), corners.end());
    addPolygon(std::move(corners), material, name);
  }
}

void SceneBuilder::addBox(Vec3 lo, Vec3 hi, int material, const std::string& name, unsigned omit) {
  static constexpr const char* kFaceName[3][2] = {{"-x", "+x"}, {"-y", "+y"}, {"-z", "+z"}};
  for (int axis = 0; axis < 3; ++axis) {
    for (int end = 0; end < 2; ++end) {
      if (omit & (1u << (2 * axis + end))) continue;  // Side bits run kXMin, kXMax, kYMin, ...
      Vec3 a = lo, b = hi;
      a[axis] = b[axis] = end == 0 ? lo[axis] : hi[axis];
      addRect(axis, end == 0 ? -1 : 1, a, b, material, "box '" + name + "' " + kFaceName[axis][end]);
    }
  }
}

void SceneBuilder::addPrism(const std::vector<Vec2>& footprint, double z0, double z1, int material,
                            const std::string& name, unsigned omit) {
  const std::string origin = "prism '" + name + "'";
  std::vector<Vec3> top, bottom;
  for (const Vec2& p : footprint) {
    top.push_back({p.x, p.y, z1});
    bottom.push_back({p.x, p.y, z0});
  }
  std::reverse(bottom.begin(), bottom.end());
  if (!(omit & kZMax)) addPolygon(top, material, origin + " top");
  if (!(omit & kZMin)) addPolygon(bottom, material, origin + " bottom");
  for (size_t i = 0; i < footprint.size(); ++i) {
    const Vec2& a = footprint[i];
    const Vec2& b = footprint[(i + 1) % footprint.size()];
    addPolygon({{a.x, a.y, z0}, {b.x, b.y, z0}, {b.x, b.y, z1}, {a.x, a.y, z1}}, material,
               origin + " side " + std::to_string(i));
  }
}

void SceneBuilder::addRoom(Vec3 lo, Vec3 hi, RoomMaterials materials, const std::vector<Opening>& openings,
                           const std::string& name) {
  static constexpr const char* kFaceName[3][2] = {
      {"wall -x", "wall +x"}, {"wall -y", "wall +y"}, {"floor", "ceiling"}};
  for (int axis = 0; axis < 3; ++axis) {
    for (int end = 0; end < 2; ++end) {
      const unsigned side = 1u << (2 * axis + end);
      const int material = axis < 2 ? materials.walls : (end == 0 ? materials.floor : materials.ceiling);
      Vec3 a = lo, b = hi;
      a[axis] = b[axis] = end == 0 ? lo[axis] : hi[axis];
      std::vector<std::pair<Vec3, Vec3>> holes;
      for (const Opening& o : openings)
        if (o.side == side) holes.emplace_back(o.lo, o.hi);
      const std::string face = "room '" + name + "' " + kFaceName[axis][end];
      addRect(axis, end == 0 ? 1 : -1, a, b, material, face, holes);  // facing inward
      for (const Opening& o : openings)
        if (o.side == side) addRecess(o, a[axis], material, face + " opening '" + o.name + "'");
    }
  }
}

// The recess behind an opening in the room face at `plane` along its side's axis: four reveals
// facing into it and, if given, a back facing the room.
void SceneBuilder::addRecess(const Opening& o, double plane, int faceMaterial, const std::string& name) {
  int axis = 0;
  while (!(o.side & (1u << (2 * axis))) && !(o.side & (1u << (2 * axis + 1)))) ++axis;
  const bool minSide = (o.side & (1u << (2 * axis))) != 0;
  const double back = plane + (minSide ? -o.depthM : o.depthM);  // behind the face, outward
  const int reveal = o.revealMaterial >= 0 ? o.revealMaterial : faceMaterial;
  if (o.depthM > 0.0) {
    for (int inPlane : {firstInPlane(axis), secondInPlane(axis)}) {
      for (int end = 0; end < 2; ++end) {
        Vec3 lo = o.lo, hi = o.hi;
        lo[axis] = std::min(plane, back);
        hi[axis] = std::max(plane, back);
        lo[inPlane] = hi[inPlane] = end == 0 ? o.lo[inPlane] : o.hi[inPlane];
        addRect(inPlane, end == 0 ? 1 : -1, lo, hi, reveal, name + " reveal");
      }
    }
  }
  if (o.backMaterial >= 0) {
    Vec3 lo = o.lo, hi = o.hi;
    lo[axis] = hi[axis] = back;
    addRect(axis, minSide ? 1 : -1, lo, hi, o.backMaterial, name + " back");
  }
}

}  // namespace radmesh
