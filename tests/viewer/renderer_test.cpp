// The renderer on hand-built meshes through OSMesa: sRGB encoding, exposure, Gouraud interpolation,
// one-sided polygons, the shooter highlight and resizing.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/cells/cell_partition.h"
#include "viewer/exposure.h"
#include "viewer/gl_context.h"
#include "viewer/offscreen_render.h"
#include "viewer/osmesa_context.h"
#include "viewer/renderer.h"

namespace radmesh {
namespace {

// The square x, z in [-1, 1] on the plane y = 0, facing -y, as two triangles of patches 0 and 1
// (the left one holds x < z... split along the diagonal from (-1,-1) to (1,1)).
DisplayMesh facingSquare() {
  DisplayMesh mesh;
  mesh.positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
  mesh.normals.assign(4, Vec3{0, -1, 0});
  mesh.indices = {0, 2, 1, 0, 3, 2};
  mesh.patchOfTriangle = {0, 1};
  return mesh;
}

// Looks at the square from y = -2 with a 90 degree field: the square fills the middle half.
RenderView frontView() { return RenderView{{0, -2, 0}, {0, 0, 0}, {0, 0, 1}, 90.0, 0.1, 10.0}; }

std::array<int, 3> pixel(const Image& image, int x, int y) {
  const size_t at = (static_cast<size_t>(y) * image.width + x) * 4;
  return {image.rgba[at], image.rgba[at + 1], image.rgba[at + 2]};
}

int srgbByte(double linear) {
  const double c = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
  return static_cast<int>(std::lround(255.0 * std::clamp(c, 0.0, 1.0)));
}

TEST(Renderer, UniformRadiosityShowsAsExposedSrgb) {
  OffscreenRenderer renderer(facingSquare(), {64, 64});
  const Rgb b{0.8, 0.4, 0.1};
  const Image image = renderer.render(std::vector<Rgb>(4, b), frontView(), {.exposure = 0.5, .highlightedPatches = {}});
  ASSERT_EQ(image.width, 64);
  ASSERT_EQ(image.height, 64);
  const auto centre = pixel(image, 32, 32);
  EXPECT_NEAR(centre[0], srgbByte(0.4), 1);
  EXPECT_NEAR(centre[1], srgbByte(0.2), 1);
  EXPECT_NEAR(centre[2], srgbByte(0.05), 1);
  // Outside the square: the clear colour, near black.
  const auto corner = pixel(image, 2, 2);
  EXPECT_LT(corner[0] + corner[1] + corner[2], 30);
}

TEST(Renderer, EncodesSrgbWithinOneLevelFromBlackToWhite) {
  // 32 vertical strips of the square, each of uniform radiosity, spread over the encoding's range
  // (its linear toe included).
  constexpr int kStrips = 32;
  DisplayMesh mesh;
  std::vector<Rgb> b;
  for (int i = 0; i < kStrips; ++i) {
    const double x0 = -1.0 + 2.0 * i / kStrips, x1 = -1.0 + 2.0 * (i + 1) / kStrips;
    const unsigned first = static_cast<unsigned>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {{x0, 0, -1}, {x1, 0, -1}, {x1, 0, 1}, {x0, 0, 1}});
    mesh.indices.insert(mesh.indices.end(), {first, first + 2, first + 1, first, first + 3, first + 2});
    mesh.patchOfTriangle.insert(mesh.patchOfTriangle.end(), {i, i});
    b.insert(b.end(), 4, Rgb{std::pow(double(i) / (kStrips - 1), 2.6)});
  }
  mesh.normals.assign(mesh.positions.size(), Vec3{0, -1, 0});
  OffscreenRenderer renderer(mesh, {256, 256});
  const Image image = renderer.render(b, frontView(), {.exposure = 1.0, .highlightedPatches = {}});
  // The square spans pixels 64..191: strip i covers columns 64 + 4i .. 64 + 4i + 3.
  for (int i = 0; i < kStrips; ++i)
    EXPECT_NEAR(pixel(image, 64 + 4 * i + 2, 128)[0], srgbByte(b[4 * i].r), 1) << "strip " << i;
}

TEST(Renderer, GouraudInterpolatesLinearRadiosityAcrossTheSquare) {
  OffscreenRenderer renderer(facingSquare(), {128, 128});
  // Radiosity 0 on the left edge, 1 on the right: linear in x.
  const std::vector<Rgb> b = {Rgb{0.0}, Rgb{1.0}, Rgb{1.0}, Rgb{0.0}};
  const Image image = renderer.render(b, frontView(), {.exposure = 1.0, .highlightedPatches = {}});
  // The square spans pixels 32..95; pixel x sits at square x = (x + 0.5 - 64) / 32.
  for (int x : {36, 48, 64, 80, 92}) {
    const double linear = ((x + 0.5 - 64.0) / 32.0 + 1.0) / 2.0;
    EXPECT_NEAR(pixel(image, x, 64)[1], srgbByte(linear), 2) << "at column " << x;
  }
}

TEST(Renderer, BackOfAOneSidedPolygonIsDarkNotLit) {
  OffscreenRenderer renderer(facingSquare(), {64, 64});
  const RenderView behind{{0, 2, 0}, {0, 0, 0}, {0, 0, 1}, 90.0, 0.1, 10.0};
  const Image image = renderer.render(std::vector<Rgb>(4, Rgb{1.0}), behind, {.exposure = 1.0, .highlightedPatches = {}});
  const auto centre = pixel(image, 32, 32);
  EXPECT_LT(centre[0], 40);
  EXPECT_GT(centre[2], centre[0]);  // the blue-grey of a back face, not the clear colour
}

// A wall of no thickness is two polygons back to back (as SketchUp and many exports draw walls).
// Seen from the front, its front shows everywhere: the back of the other face, at the same depth
// but for rounding, shows nowhere (it showed in blotches of blue-grey before 2026-12-04).
TEST(Renderer, AWallOfNoThicknessShowsItsFrontNotTheBackBehindIt) {
  DisplayMesh mesh;
  constexpr int kCuts = 8;  // the back face cut otherwise than the front, so its depths round otherwise
  mesh.positions = {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}};
  mesh.normals.assign(4, Vec3{0, -1, 0});
  mesh.indices = {0, 2, 1, 0, 3, 2};
  mesh.patchOfTriangle = {0, 0};
  for (int i = 0; i < kCuts; ++i) {
    const double x0 = -1.0 + 2.0 * i / kCuts, x1 = -1.0 + 2.0 * (i + 1) / kCuts;
    const unsigned first = static_cast<unsigned>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {{x0, 0, -1}, {x1, 0, -1}, {x1, 0, 1}, {x0, 0, 1}});
    mesh.normals.insert(mesh.normals.end(), 4, Vec3{0, 1, 0});
    mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 3, first + 1, first + 2, first + 3});
    mesh.patchOfTriangle.insert(mesh.patchOfTriangle.end(), {1, 1});
  }
  OffscreenRenderer renderer(mesh, {256, 256});
  std::vector<Rgb> b(mesh.positions.size(), Rgb{0.5});
  const RenderView oblique{{-1.5, -1.2, 0.4}, {0.3, 0, -0.1}, {0, 0, 1}, 70.0, 0.1, 10.0};
  const Image image = renderer.render(b, oblique, {.exposure = 1.0, .highlightedPatches = {}});
  const auto near = [](const std::array<int, 3>& p, const std::array<int, 3>& q) {
    return std::abs(p[0] - q[0]) <= 3 && std::abs(p[1] - q[1]) <= 3 && std::abs(p[2] - q[2]) <= 3;
  };
  const std::array<int, 3> grey{srgbByte(0.5), srgbByte(0.5), srgbByte(0.5)};
  const std::array<int, 3> backColour{srgbByte(0.010), srgbByte(0.012), srgbByte(0.020)};
  int front = 0, back = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      front += near(pixel(image, x, y), grey);
      back += near(pixel(image, x, y), backColour);
    }
  EXPECT_GT(front, 10000);
  EXPECT_EQ(back, 0);
}

TEST(Renderer, HighlightTintsOnlyTheShootingPatch) {
  OffscreenRenderer renderer(facingSquare(), {64, 64});
  const std::vector<Rgb> grey(4, Rgb{0.2});
  OffscreenShading shading{.exposure = 1.0, .highlightedPatches = {1}};
  const Image image = renderer.render(grey, frontView(), shading);
  // Patch 1 is the triangle (0, 3, 2): upper left in the image. Patch 0 is lower right.
  const auto inShooter = pixel(image, 24, 20);
  const auto outside = pixel(image, 44, 44);
  EXPECT_NEAR(outside[0], srgbByte(0.2), 1);
  EXPECT_NEAR(outside[1], srgbByte(0.2), 1);
  EXPECT_GT(inShooter[0], inShooter[1] + 40);  // magenta: red and blue over green
  EXPECT_GT(inShooter[2], inShooter[1] + 40);
}

TEST(Renderer, ResizedContextDrawsAtTheNewSize) {
  OsMesaContext context({32, 32});
  {
    Renderer renderer;
    renderer.setMesh(facingSquare());
    renderer.setVertexRadiosity(std::vector<Rgb>(4, Rgb{0.5}));
    context.resize({96, 48});
    renderer.draw(frontView(), context.framebufferSize(), Shading{1.0, false});
    const Image image = captureFramebuffer(context.framebufferSize());
    ASSERT_EQ(image.width, 96);
    ASSERT_EQ(image.height, 48);
    // Wider than tall: the square stays square, 24 pixels high and wide around the centre.
    EXPECT_NEAR(pixel(image, 48, 24)[0], srgbByte(0.5), 1);
    EXPECT_EQ(pixel(image, 48 - 30, 24)[0], pixel(image, 2, 2)[0]);
  }
}

// Triangles grouped by cell: a cell left out is not drawn, the patches facing no cell always are.
TEST(Renderer, DrawsOnlyTheVisibleCellsAndTheOutside) {
  OsMesaContext context({64, 64});
  Renderer renderer;
  renderer.setMesh(facingSquare());
  renderer.setVertexRadiosity(std::vector<Rgb>(4, Rgb{0.5}));
  // Patch 0 (x > z, right of the middle row) and patch 1 (left of it).
  auto drawn = [&](const std::vector<int>& cellOfPatch, int cells, std::vector<bool> visible) {
    renderer.setCells(cellOfPatch, cells);
    renderer.setVisibleCells(std::move(visible));
    renderer.draw(frontView(), context.framebufferSize(), Shading{1.0, false});
    const Image image = captureFramebuffer(context.framebufferSize());
    auto lit = [&](int x) { return std::abs(pixel(image, x, 32)[0] - srgbByte(0.5)) <= 1; };
    return std::array<bool, 2>{lit(42), lit(22)};
  };
  EXPECT_EQ(drawn({1, 0}, 2, {true, false}), (std::array<bool, 2>{false, true}));
  EXPECT_EQ(drawn({1, 0}, 2, {false, true}), (std::array<bool, 2>{true, false}));
  EXPECT_EQ(drawn({1, 0}, 2, {false, false}), (std::array<bool, 2>{false, false}));
  EXPECT_EQ(drawn({1, 0}, 2, {}), (std::array<bool, 2>{true, true})) << "no visibility: every cell";
  EXPECT_EQ(drawn({kOutsideCell, 0}, 1, {false}), (std::array<bool, 2>{true, false})) << "the outside is drawn";
  EXPECT_THROW(renderer.setCells({0}, 1), std::invalid_argument);
}

TEST(Renderer, RefusesRadiosityOfTheWrongLength) {
  OffscreenRenderer renderer(facingSquare(), {16, 16});
  EXPECT_THROW(renderer.render(std::vector<Rgb>(3, Rgb{1.0}), frontView()), std::invalid_argument);
}

TEST(Renderer, RefusesADegenerateView) {
  OffscreenRenderer renderer(facingSquare(), {16, 16});
  RenderView view = frontView();
  view.look = view.eye;
  EXPECT_THROW(renderer.render(std::vector<Rgb>(4, Rgb{1.0}), view), std::invalid_argument);
}

}  // namespace
}  // namespace radmesh
