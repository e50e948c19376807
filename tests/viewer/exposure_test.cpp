#include "viewer/exposure.h"

#include <gtest/gtest.h>

#include <cmath>
#include <ostream>

#include "solver/io/mgf_color.h"
#include "solver/io/scene_loader.h"
#include "solver/meshing/meshing.h"
#include "solver/radiosity/progressive_solver.h"
#include "tests/test_paths.h"
#include "viewer/camera.h"
#include "viewer/offscreen_render.h"

namespace radmesh {

void PrintTo(const StopsSpan& span, std::ostream* os) { *os << span.low << ".." << span.high; }

namespace {

// A right triangle of legs a (area a²/2) in the plane z = 0, its three corners at luminance b.
void addTriangle(DisplayMesh& mesh, std::vector<Rgb>& vertexB, double x, double a, double b) {
  const unsigned first = static_cast<unsigned>(mesh.positions.size());
  for (const Vec3& p : {Vec3{x, 0, 0}, Vec3{x + a, 0, 0}, Vec3{x, a, 0}}) {
    mesh.positions.push_back(p);
    vertexB.push_back(Rgb{b});
  }
  for (unsigned i = 0; i < 3; ++i) mesh.indices.push_back(first + i);
}

TEST(Exposure, MapsThe95thPercentileOfAreaToBelowWhite) {
  ASSERT_NEAR(luminance(Rgb{1.0}), 1.0, 1e-12);
  // A wall at luminance 2 and a light at 100 with 3 % of the area: the light is above the 95th
  // percentile, so the wall sets the exposure and the light alone clips.
  DisplayMesh mesh;
  std::vector<Rgb> b;
  addTriangle(mesh, b, 0.0, 3.0, 2.0);     // area 4.5
  addTriangle(mesh, b, 10.0, 0.5, 100.0);  // area 0.125
  EXPECT_NEAR(autoExposure(mesh, b), 0.7 / 2.0, 1e-12);
  // Many small bright triangles (a detailed desk) do not outvote a large dark one by their count.
  for (int i = 0; i < 50; ++i) addTriangle(mesh, b, 20.0 + i, 0.01, 50.0);
  EXPECT_NEAR(autoExposure(mesh, b), 0.7 / 2.0, 1e-12);
}

TEST(Exposure, FallsBackToTheBrightestWhileMostIsDark) {
  DisplayMesh mesh;
  std::vector<Rgb> b;
  addTriangle(mesh, b, 0.0, 10.0, 0.0);
  addTriangle(mesh, b, 20.0, 1.0, 10.0);
  EXPECT_DOUBLE_EQ(autoExposure(mesh, b), 0.7 / 10.0);
}

TEST(Exposure, IsOneWhenNothingIsLit) {
  EXPECT_DOUBLE_EQ(autoExposure({}, {}), 1.0);
  DisplayMesh mesh;
  std::vector<Rgb> b;
  addTriangle(mesh, b, 0.0, 1.0, 0.0);
  EXPECT_DOUBLE_EQ(autoExposure(mesh, b), 1.0);
}

// A solve's doubles reach far below a float's: 1e-300 W/m^2 made it +1010 EV (radmesh render said
// so, and --exposure refused it back). It stops at kMaxExposureStops either way.
TEST(Exposure, StaysWithinTheStopsRenderTakes) {
  for (const auto& [luminance, stops] : {std::pair{1e-300, kMaxExposureStops}, std::pair{1e300, -kMaxExposureStops},
                                         std::pair{1e-40, std::log2(0.7 / 1e-40)}}) {
    DisplayMesh mesh;
    std::vector<Rgb> b;
    addTriangle(mesh, b, 0.0, 1.0, luminance);
    EXPECT_DOUBLE_EQ(std::log2(autoExposure(mesh, b)), stops) << luminance;
  }
}

// The panel's exposure slider shows any value --exposure takes where it is, not pinned at an end of
// -20..20 (--exposure 40 was), and keeps its span while dragged, to its ends too.
TEST(Exposure, TheSliderSpansWhatItShows) {
  const StopsSpan first;
  EXPECT_EQ(exposureSliderSpan(-3.5, first), (StopsSpan{-20.0, 20.0}));
  EXPECT_EQ(exposureSliderSpan(40.0, first), (StopsSpan{20.0, 60.0}));
  EXPECT_EQ(exposureSliderSpan(-41.3, first), (StopsSpan{-61.0, -21.0}));
  EXPECT_EQ(exposureSliderSpan(kMaxExposureStops, first), (StopsSpan{120.0, 160.0}));
  EXPECT_EQ(exposureSliderSpan(-kMaxExposureStops, first), (StopsSpan{-160.0, -120.0}));
  // Dragged to either end, it stays; a value from elsewhere in -20..20 brings the first span back.
  const StopsSpan high{20.0, 60.0};
  EXPECT_EQ(exposureSliderSpan(20.0, high), high);
  EXPECT_EQ(exposureSliderSpan(60.0, high), high);
  EXPECT_EQ(exposureSliderSpan(5.0, high), first);
  EXPECT_EQ(exposureSliderSpan(-20.0, first), first);
}

// Fraction of the pixels of `image` at the ceiling value in some channel.
double clippedFraction(const Image& image) {
  size_t clipped = 0;
  for (size_t i = 0; i < image.rgba.size(); i += 4)
    clipped += image.rgba[i] == 255 || image.rgba[i + 1] == 255 || image.rgba[i + 2] == 255;
  return double(clipped) / double(image.rgba.size() / 4);
}

struct Shown {
  DisplayMesh mesh;
  std::vector<Rgb> vertexB;
};

// The scene solved on the hemicube to `options`' stops, as the renderer is given it.
Shown solvedAndShown(const Scene& scene, double cellM, SolveOptions options) {
  options.projection = Projection::Hemicube;
  ProgressiveSolver solver(scene, meshScene(scene, cellM), options);
  while (!solver.done()) solver.step();
  Shown shown{buildDisplayMesh(solver.patches()), {}};
  shown.vertexB = vertexRadiosity(shown.mesh, solver.displayRadiosity());
  return shown;
}

// office3 converged (to 5 % unshot): the rule that took the 95th percentile of the vertices put
// two-thirds of this picture at the ceiling value, its thousands of small desk polygons outvoting
// the walls. By area, only the light in view clips.
TEST(Exposure, LeavesLittleOfAConvergedOfficeClipped) {
  RADMESH_REQUIRE_SHARED(office3, "scenes/mgf/office3/office.mgf");
  const Scene scene = loadScene(office3.string());
  SolveOptions options;
  options.resolution = 64;
  options.until = 1.0;
  options.untilUnshot = 0.05;
  const Shown shown = solvedAndShown(scene, 1.0, options);
  OffscreenRenderer renderer(shown.mesh, {320, 240});
  const Image image = renderer.render(shown.vertexB, WalkCamera(sceneFrame(scene)).view());
  const double clipped = clippedFraction(image);
  EXPECT_LT(clipped, 0.05) << clipped;  // 0.033: the ceiling light in view
}

// The automatic exposure makes the picture independent of the light's scale, over all a scene may
// hold (emitters from 1e-30 to 1e30 W/m^2; beyond, they are refused as read) and past a float's
// range: radiosity of 1e300 W/m^2 (an `ed 1e306` lamp, refused now) drew all black, inf times 0.
// Further out the exposure stops at kMaxExposureStops (StaysWithinTheStopsRenderTakes).
TEST(Exposure, AnyScaleOfTheLightDrawsTheSamePicture) {
  const Scene scene = loadScene("cornell");
  SolveOptions options;
  options.resolution = 32;
  options.maxIterations = 30;
  const auto [mesh, vertexB] = solvedAndShown(scene, 0.1, options);
  OffscreenRenderer renderer(mesh, {160, 120});
  const RenderView view = WalkCamera(sceneFrame(scene)).view();
  const Image plain = renderer.render(vertexB, view);
  for (const double scale : {1e40, 1e-40}) {
    std::vector<Rgb> scaled = vertexB;
    for (Rgb& b : scaled) b *= scale;
    const Image image = renderer.render(scaled, view);
    ASSERT_EQ(image.rgba.size(), plain.rgba.size());
    int worst = 0;
    for (size_t i = 0; i < image.rgba.size(); ++i) worst = std::max(worst, std::abs(image.rgba[i] - plain.rgba[i]));
    EXPECT_LE(worst, 1) << "radiosity times " << scale;
  }
  long lit = 0;
  for (size_t i = 0; i < plain.rgba.size(); i += 4) lit += plain.rgba[i] > 20;
  EXPECT_GT(lit, 160 * 120 / 2);  // the picture is not black to begin with
}

}  // namespace
}  // namespace radmesh
