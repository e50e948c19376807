#include "viewer/cell_plan.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <string>

#include "solver/scene/up_axis.h"

namespace radmesh {

namespace {

constexpr double kCutHeightM = 1.0;  // walls are cut here above the lowest floor, as plans are drawn
using Rgb8 = std::array<std::uint8_t, 3>;
constexpr Rgb8 kBackground{250, 250, 250}, kWall{40, 40, 48}, kPortal{255, 0, 200};

class Canvas {
 public:
  Canvas(const Vec3& lo, const Vec3& hi) : lo_(lo) {
    const auto [w, h] = cellPlanSize(lo, hi);
    image_ = Image{w, h, std::vector<std::uint8_t>(size_t(w) * h * 4, 255)};
    scale_ = double(kPlanLongSidePx) / std::max({hi.x - lo.x, hi.y - lo.y, 1e-9});
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) set(x, y, kBackground);
  }

  // Pixel coordinates of a point seen from above: x to the right, y (north) up.
  Vec2 toPixel(const Vec3& p) const {
    return {kPlanMarginPx + (p.x - lo_.x) * scale_, image_.height - kPlanMarginPx - (p.y - lo_.y) * scale_};
  }

  void set(int x, int y, const Rgb8& c) {
    if (x < 0 || y < 0 || x >= image_.width || y >= image_.height) return;
    std::uint8_t* px = &image_.rgba[(size_t(y) * image_.width + x) * 4];
    std::copy(c.begin(), c.end(), px);
    px[3] = 255;
  }

  // Pixels whose centres lie inside the convex polygon (either winding).
  void fill(const std::vector<Vec2>& polygon, const Rgb8& c) {
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const Vec2& p : polygon) {
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    const double area = signedArea(polygon);
    if (std::abs(area) < 1e-12) return;
    for (int y = int(std::floor(y0)); y <= int(std::ceil(y1)); ++y)
      for (int x = int(std::floor(x0)); x <= int(std::ceil(x1)); ++x) {
        const Vec2 centre{x + 0.5, y + 0.5};
        bool inside = true;
        for (size_t k = 0; k < polygon.size() && inside; ++k)
          inside = cross2(polygon[(k + 1) % polygon.size()] - polygon[k], centre - polygon[k]) * area >= 0.0;
        if (inside) set(x, y, c);
      }
  }

  // A line `width` pixels thick.
  void line(Vec2 a, Vec2 b, double width, const Rgb8& c) {
    const int steps = int(std::ceil(glm::length(b - a))) + 1;
    const int r = int(std::floor(width / 2));
    for (int k = 0; k <= steps; ++k) {
      const Vec2 p = a + (b - a) * (double(k) / steps);
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) set(int(std::floor(p.x)) + dx, int(std::floor(p.y)) + dy, c);
    }
  }

  // A number in a 3 x 5 pixel font scaled `scale` times, centred on p.
  void number(int value, Vec2 p, int scale, const Rgb8& c) {
    static constexpr const char* kDigits[10] = {"111101101101111", "010110010010111", "111001111100111",
                                                "111001111001111", "101101111001001", "111100111001111",
                                                "111100111101111", "111001001001001", "111101111101111",
                                                "111101111001111"};
    const std::string text = std::to_string(value);
    const int width = int(text.size()) * 4 * scale - scale;
    const int x0 = int(p.x) - width / 2, y0 = int(p.y) - 5 * scale / 2;
    for (size_t k = 0; k < text.size(); ++k)
      for (int row = 0; row < 5; ++row)
        for (int col = 0; col < 3; ++col)
          if (kDigits[text[k] - '0'][row * 3 + col] == '1')
            for (int dy = 0; dy < scale; ++dy)
              for (int dx = 0; dx < scale; ++dx)
                set(x0 + int(k) * 4 * scale + col * scale + dx, y0 + row * scale + dy, c);
  }

  Image take() { return std::move(image_); }

 private:
  Vec3 lo_;
  double scale_ = 1.0;
  Image image_;
};

// A vertical polygon's trace on the plan: the two points of its footprint farthest apart.
std::pair<Vec2, Vec2> trace(const std::vector<Vec2>& footprint) {
  std::pair<Vec2, Vec2> ends{footprint[0], footprint[0]};
  for (const Vec2& a : footprint)
    for (const Vec2& b : footprint)
      if (glm::length(b - a) > glm::length(ends.second - ends.first)) ends = {a, b};
  return ends;
}

Rgb8 shade(const Rgb8& c, double f) {
  return {std::uint8_t(c[0] * f), std::uint8_t(c[1] * f), std::uint8_t(c[2] * f)};
}

}  // namespace

std::pair<int, int> cellPlanSize(const Vec3& lo, const Vec3& hi) {
  const double scale = double(kPlanLongSidePx) / std::max({hi.x - lo.x, hi.y - lo.y, 1e-9});
  return {int(std::lround((hi.x - lo.x) * scale)) + 2 * kPlanMarginPx,
          int(std::lround((hi.y - lo.y) * scale)) + 2 * kPlanMarginPx};
}

// Hues a golden angle apart, the saturation stepping with the index too (cells 21 apart, the
// golden angle's near-return, differ in it), pale enough for the walls and portals to stand out.
std::array<std::uint8_t, 3> cellPlanColour(int cell) {
  if (cell < 0) return {170, 170, 170};
  static constexpr double kSaturation[4] = {0.55, 0.35, 0.7, 0.45};
  const double h = std::fmod(cell * 0.618033988749895, 1.0) * 6.0, s = kSaturation[cell % 4], v = 0.95;
  const int sector = int(h);
  const double f = h - sector, p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  const std::array<std::array<double, 3>, 6> rgb{{{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}}};
  const auto& c = rgb[sector % 6];
  return {std::uint8_t(std::lround(c[0] * 255)), std::uint8_t(std::lround(c[1] * 255)),
          std::uint8_t(std::lround(c[2] * 255))};
}

namespace {

// The scene turned so that its up axis is z (across, along, up of its UpFrame): the plan below
// is drawn down z. A rotation: lengths and the picture's proportions stay.
struct PlanFrame {
  UpFrame axes;
  Vec3 operator()(const Vec3& p) const { return {glm::dot(p, axes.across), glm::dot(p, axes.along), glm::dot(p, axes.up)}; }
};

}  // namespace

Image drawCellPlan(const std::vector<Patch>& scenePatches, const CellPartition& sceneCells, int upAxis) {
  const PlanFrame toPlan{upFrame(upAxis)};
  std::vector<Patch> patches = scenePatches;
  for (Patch& p : patches) {
    for (int k = 0; k < p.vertexCount; ++k) p.vertices[k] = toPlan(p.vertices[k]);
    p.centroid = toPlan(p.centroid);
    p.normal = toPlan(p.normal);
  }
  CellPartition cells = sceneCells;
  for (Cell& c : cells.cells) {
    const Vec3 a = toPlan(c.boundsMin), b = toPlan(c.boundsMax);
    c.boundsMin = glm::min(a, b);
    c.boundsMax = glm::max(a, b);
  }
  for (Portal& portal : cells.portals)
    for (Vec3& v : portal.vertices) v = toPlan(v);
  Vec3 lo(1e300), hi(-1e300);
  for (const Patch& p : patches)
    for (int k = 0; k < p.vertexCount; ++k) {
      lo = glm::min(lo, p.vertices[k]);
      hi = glm::max(hi, p.vertices[k]);
    }
  if (patches.empty()) lo = hi = Vec3(0.0);
  Canvas canvas(lo, hi);
  auto footprint = [&](const Patch& p) {
    std::vector<Vec2> out;
    for (int k = 0; k < p.vertexCount; ++k) out.push_back(canvas.toPixel(p.vertices[k]));
    return out;
  };
  // Floors, then what stands on them, lowest first; a top above the floor a shade darker.
  std::vector<size_t> up;
  for (size_t i = 0; i < patches.size(); ++i)
    if (patches[i].normal.z > 0.5) up.push_back(i);
  std::stable_sort(up.begin(), up.end(), [&](size_t a, size_t b) { return patches[a].centroid.z < patches[b].centroid.z; });
  for (size_t i : up) {
    const Rgb8 colour = cellPlanColour(cells.cellOfPatch[i]);
    canvas.fill(footprint(patches[i]), patches[i].centroid.z > lo.z + 0.05 ? shade(colour, 0.8) : colour);
  }
  // Walls and furniture sides standing across the cut height.
  const double cut = lo.z + kCutHeightM;
  for (const Patch& p : patches) {
    if (std::abs(p.normal.z) > 0.1) continue;
    double z0 = 1e300, z1 = -1e300;
    for (int k = 0; k < p.vertexCount; ++k) z0 = std::min(z0, p.vertices[k].z), z1 = std::max(z1, p.vertices[k].z);
    if (z0 > cut || z1 < cut) continue;
    const auto [a, b] = trace(footprint(p));
    canvas.line(a, b, 2.0, kWall);
  }
  for (const Portal& portal : cells.portals) {
    std::vector<Vec2> f;
    for (const Vec3& v : portal.vertices) f.push_back(canvas.toPixel(v));
    const auto [a, b] = trace(f);
    canvas.line(a, b, 7.0, kWall);  // outlined, to stand out against any cell's colour
    canvas.line(a, b, 3.0, kPortal);
  }
  // Each cell's number at the middle of its bounds.
  for (size_t c = 0; c < cells.cells.size(); ++c) {
    const Cell& cell = cells.cells[c];
    canvas.number(int(c), canvas.toPixel(0.5 * (cell.boundsMin + cell.boundsMax)), 3, kWall);
  }
  return canvas.take();
}

}  // namespace radmesh
