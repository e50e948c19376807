// The first shot of lights without a patch (solver/formfactors/light_rows.h): closed forms for the
// direct light of a point light on a 64 x 64 wall, a spot's cone, and the sun on a plane with a
// shadow; the energy they send; and the two back ends' agreement.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "parallel/thread_pool.h"
#include "solver/formfactors/light_rows.h"
#include "solver/io/scene_loader.h"
#include "solver/meshing/meshing.h"
#include "solver/projection/projection.h"
#include "solver/radiosity/progressive_solver.h"
#include "solver/scene/sun.h"
#include "tests/test_paths.h"

namespace radmesh {
namespace {

constexpr double kPi = std::numbers::pi;

// tests/data/lights/point_box.gltf: the box [0, 2]^3 (grey, rho 0.5), a 179 cd white point light
// (1 W/sr per channel) at its centre.
Scene pointBox() { return loadScene(test::dataPath("lights/point_box.gltf").string()); }

SolveOptions lightOptions(Backend backend = Backend::Native) {
  SolveOptions o;
  o.backend = backend;
  o.projection = Projection::Plane;
  o.resolution = 256;
  o.threads = 1;
  return o;
}

// The direct irradiance on each patch after the first iteration (the lights' shot): B / rho.
std::vector<double> directIrradiance(const ProgressiveSolver& solver) {
  std::vector<double> e;
  for (size_t j = 0; j < solver.patches().size(); ++j)
    e.push_back(solver.radiosity()[j].r / solver.scene().materials[solver.patches()[j].material].rho.r);
  return e;
}

// Solid angle of the rectangle [x0, x1] x [y0, y1] on a plane at distance d, seen from the foot's
// normal line: the integral of cos(theta) / r^2 over it.
double rectangleSolidAngle(double x0, double x1, double y0, double y1, double d) {
  auto corner = [d](double x, double y) { return std::atan(x * y / (d * std::sqrt(x * x + y * y + d * d))); };
  return corner(x1, y1) - corner(x0, y1) - corner(x1, y0) + corner(x0, y0);
}

TEST(LightShot, PointLightOnA64x64WallMatchesTheInverseSquareCosineLawPerPatch) {
  const Scene scene = pointBox();
  ProgressiveSolver solver(scene, meshScene(scene, 2.0 / 64), lightOptions());
  solver.step();
  const std::vector<double> e = directIrradiance(solver);
  int ceiling = 0;
  double worst = 0.0;
  for (size_t j = 0; j < e.size(); ++j) {
    const Patch& p = solver.patches()[j];
    if (p.centroid.z < 2.0 - 1e-9) continue;
    ++ceiling;
    double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
    for (int k = 0; k < p.vertexCount; ++k) {
      x0 = std::min(x0, p.vertices[k].x - 1.0), x1 = std::max(x1, p.vertices[k].x - 1.0);
      y0 = std::min(y0, p.vertices[k].y - 1.0), y1 = std::max(y1, p.vertices[k].y - 1.0);
    }
    const double closedForm = 1.0 * rectangleSolidAngle(x0, x1, y0, y1, 1.0) / p.areaM2;  // I Omega / A
    worst = std::max(worst, std::abs(e[j] / closedForm - 1.0));
  }
  EXPECT_EQ(ceiling, 64 * 64);
  EXPECT_LT(worst, 0.01);  // the criterion
  EXPECT_LT(worst, 1e-4);  // 4 x 4 pixels per patch, aligned with them: 1.2e-5 measured
  RecordProperty("worst_relative_error", std::to_string(worst));
  std::printf("point light, 64x64 ceiling at N = 256: worst per-patch error %.3g\n", worst);
}

TEST(LightShot, PointLightInAClosedBoxSendsAll4PiIAndTheLedgerBalancesEveryIteration) {
  const Scene scene = pointBox();
  ProgressiveSolver solver(scene, meshScene(scene, 0.25), lightOptions());
  const double power = 3 * 4 * kPi * 1.0;  // three channels of 1 W/sr
  EXPECT_NEAR(solver.ledger().emitted, power, 1e-12 * power);
  const IterationRecord& first = solver.step();
  EXPECT_TRUE(first.shooters.empty());  // the light shot, no patch
  EXPECT_NEAR(first.shotPowerW, power, 1e-12 * power);
  EXPECT_NEAR(first.ledger.absorbed + first.ledger.unshot, power, 1e-9 * power);
  EXPECT_EQ(first.ledger.escaped, 0.0);
  EXPECT_EQ(first.ledger.notCaptured, 0.0);
  EXPECT_NEAR(first.ledger.unshot, 0.5 * power, 1e-9 * power);  // rho 0.5 everywhere
  for (int i = 0; i < 200 && !solver.done(); ++i) EXPECT_LE(solver.step().ledger.imbalance(), 1e-9);
}

// The sun on a closed room lit by its ceiling lands on its outside: that power never came in, so
// the stopping rule measures the unshot power against the ceiling's alone, and the room is solved.
TEST(LightShot, SunOnTheOutsideDoesNotCountTowardsTheUnshotFraction) {
  Daylight daylight;
  daylight.sun = {parseSun("30,40")};
  const Scene room = loadScene(test::dataPath("yup_room.gltf").string(), nullptr, daylight);
  SolveOptions options = lightOptions();
  options.resolution = 64;
  options.until = 1.0;  // on the unshot power alone
  options.untilUnshot = 0.01;
  ProgressiveSolver solver(room, meshScene(room, 0.5), options);
  const IterationRecord& first = solver.step();
  const Rgb sun = lightPower(room, room.lights.back());
  const double sunW = sun.r + sun.g + sun.b;
  EXPECT_GT(first.ledger.lightOutside, 0.99 * sunW);  // all but what slips in at edges
  EXPECT_LE(first.ledger.lightOutside, sunW * (1 + 1e-12));
  // Of it, what fell on the walls' backs is kept apart from what went past: nothing else has escaped
  // or reached a back yet.
  EXPECT_GT(first.ledger.lightOnBackFaces, 0.0);
  EXPECT_EQ(first.ledger.lightOnBackFaces, first.ledger.absorbedByBackFaces);
  EXPECT_NEAR(first.ledger.lightOnBackFaces + first.ledger.escaped, first.ledger.lightOutside, 1e-12 * sunW);
  EXPECT_GT(first.ledger.unshotFraction(), 0.5);  // the ceiling's light, not yet shot
  EXPECT_FALSE(solver.done());
  int iterations = 1;
  while (!solver.done()) ++iterations, solver.step();
  EXPECT_GT(iterations, 20);
  EXPECT_LE(solver.ledger().unshotFraction(), 0.01);
  EXPECT_LE(solver.ledger().imbalance(), 1e-9);
}

// The sun on a closed room lands on its outside only. A pixel centre within 1e-4 pixel of a
// corner where a wall meets the floor saw the wall's outside and the floor's inside at depths
// equal to 1e-6, a depth tie, which the floor won by rank: 2 pixels of the sun at N = 256 (3e-5 of
// it, a bright strip at a wall's foot) until a beam's ties were made rounding-tight
// (kBeamDepthTieTolerance, solver/projection/scan_conversion.h).
TEST(LightShot, TheSunDoesNotSlipIntoAClosedRoomThroughItsSeams) {
  Daylight daylight;
  daylight.sun = {parseSun("30,40")};
  const Scene room = loadScene(test::dataPath("yup_room.gltf").string(), nullptr, daylight);
  ThreadPool pool(1);
  for (double cellM : {0.5, 0.25})
    for (int resolution : {64, 256, 512}) {
      const std::vector<Patch> patches = meshScene(room, cellM);
      const FormFactorRow row = lightRow(room, room.lights.back(), patches, resolution, sceneNearDepth(patches), pool);
      double inside = 0.0;
      for (double f : row.formFactors) inside += f;
      EXPECT_EQ(inside, 0.0) << "cell " << cellM << " m, N = " << resolution << ": " << row.receivers.size()
                             << " patches lit inside";
      EXPECT_GT(row.backFaces, 0.1);  // the walls' and the roof's outsides
      EXPECT_NEAR(row.backFaces + row.escapedFraction(), 1.0, 1e-12);
    }
}

// Many lights' rows over one set of patches (LightRows: the point lights share one projection) are
// bitwise each light's own lightRow, a spot and the sun among them, the sky in a window left out.
TEST(LightShot, ManyLightsRowsAreEachLightsOwnBitForBit) {
  Daylight daylight;
  daylight.skyLux = 10000;
  daylight.sun = {parseSun("180,40")};  // into the box's opening
  Scene room = loadScene(test::dataPath("lights/open_box.gltf").string(), nullptr, daylight);
  Light point = pointBox().lights[0], spot = point;
  spot.type = LightType::Spot;
  spot.direction = Vec3(0.0, -1.0, 0.0);
  spot.outerConeRad = 0.6;
  room.lights.insert(room.lights.begin(), {point, point, spot, point});
  room.lights[0].position = Vec3(0.4, 1.7, 0.3);
  room.lights[1].position = Vec3(1.5, 0.5, 1.2);
  room.lights[2].position = Vec3(1.0, 1.8, 1.0);
  room.lights[3].position = Vec3(0.7, 1.1, 1.6);
  const std::vector<Patch> patches = meshScene(room, 0.25);
  ASSERT_TRUE(std::ranges::any_of(patches, [&](const Patch& p) { return room.materials[p.material].skyOpening; }));
  ThreadPool pool(2);
  const double nearDepth = sceneNearDepth(patches);
  LightRows rows(room, patches, 64, nearDepth, pool);
  for (size_t k = 0; k < room.lights.size(); ++k) {
    const FormFactorRow many = rows.row(room.lights[k]);
    const FormFactorRow own = lightRow(room, room.lights[k], patches, 64, nearDepth, pool);
    EXPECT_EQ(many.receivers, own.receivers) << "light " << k;
    EXPECT_EQ(many.formFactors, own.formFactors) << "light " << k;
    EXPECT_EQ(many.backFaces, own.backFaces) << "light " << k;
    EXPECT_GT(own.receivers.size(), 10u) << "light " << k;
  }
}

TEST(LightShot, TheCubeAndTheSpotsFalloffIntegrateToTheirClosedForms) {
  Scene scene = pointBox();
  const ProjectionSurface cube = lightSurface(scene, scene.lights[0], 256);
  EXPECT_EQ(cube.faces.size(), 6u);
  EXPECT_NEAR(cube.tableSum, 4 * kPi, 1e-4 * 4 * kPi);  // the sampled solid angles
  Light spot;
  spot.type = LightType::Spot;
  spot.innerConeRad = 0.3;
  spot.outerConeRad = 0.6;
  spot.intensity = Rgb(1.0);
  const double cone = 2 * kPi * ((1 - std::cos(0.3)) + (std::cos(0.3) - std::cos(0.6)) / 3);
  const ProjectionSurface hemicube = lightSurface(scene, spot, 256);
  EXPECT_EQ(hemicube.faces.size(), 5u);
  EXPECT_NEAR(hemicube.tableSum, cone, 2e-3 * cone);
  const Rgb power = lightPower(scene, spot);
  EXPECT_NEAR(power.r + power.g + power.b, 3 * cone, 1e-14);
}

TEST(LightShot, SpotLightPowerIsItsConeIntegralAndLightsOnlyItsCone) {
  Scene scene = pointBox();
  Light& spot = scene.lights[0];
  spot.type = LightType::Spot;
  spot.direction = Vec3(0.0, 0.0, -1.0);  // down at the floor, 1 m below
  spot.innerConeRad = 0.3;
  spot.outerConeRad = 0.6;
  ProgressiveSolver solver(scene, meshScene(scene, 2.0 / 32), lightOptions());
  const double power = 3 * 2 * kPi * ((1 - std::cos(0.3)) + (std::cos(0.3) - std::cos(0.6)) / 3);
  const IterationRecord& first = solver.step();
  EXPECT_NEAR(first.ledger.emitted, power, 1e-12 * power);
  EXPECT_NEAR(first.ledger.absorbed + first.ledger.unshot, power, 1e-9 * power);
  const std::vector<double> e = directIrradiance(solver);
  int lit = 0;
  for (size_t j = 0; j < e.size(); ++j) {
    const Vec3 c = solver.patches()[j].centroid;
    const double radius = std::hypot(c.x - 1.0, c.y - 1.0);
    if (c.z > 1e-9 || radius > std::tan(0.6) + 0.05) {
      EXPECT_EQ(e[j], 0.0) << "patch " << j << " outside the cone";  // walls, ceiling, far floor
    } else if (radius < 0.2) {
      EXPECT_NEAR(e[j], 1.0 / std::pow(1 + radius * radius, 1.5), 0.01);  // inside the inner cone: I cos / r^2
    }
    lit += e[j] > 0.0;
  }
  EXPECT_GT(lit, 0);
}

// The plane [0, 1]^2 (z = 0, facing up), meshed 16 x 16, and optionally the square
// [0.25, 0.5]^2 at z = 0.5 above it, both rho 0.5.
Scene planeScene(bool occluder) {
  Scene s;
  s.source = "sun plane";
  s.materials.push_back({"grey", Rgb(0.5), Rgb(0.0)});
  s.polygons.push_back({{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, 0, "plane"});
  if (occluder) s.polygons.push_back({{{0.25, 0.25, 0.5}, {0.5, 0.25, 0.5}, {0.5, 0.5, 0.5}, {0.25, 0.5, 0.5}}, 0, "square"});
  return s;
}

TEST(LightShot, SunOnAPlaneGivesECosThetaOnEveryPatch) {
  Scene scene = planeScene(false);
  scene.lights.push_back(sunLight(0.0, 60.0, kWhiteEfficacyLmPerW));  // E = 1 W/m^2 per channel
  ProgressiveSolver solver(scene, meshScene(scene, 1.0 / 16), lightOptions());
  const IterationRecord& first = solver.step();
  const std::vector<double> e = directIrradiance(solver);
  ASSERT_EQ(e.size(), 256u);
  for (double irradiance : e) EXPECT_NEAR(irradiance, std::sin(kPi / 3), 1e-12);
  EXPECT_LE(first.ledger.imbalance(), 1e-9);
  EXPECT_LE(first.ledger.escaped, 1e-12 * first.ledger.emitted);  // the window is the plane's shadow, all of it
}

TEST(LightShot, OverheadSunCastsTheOccludersShadowOnExactly16Patches) {
  Scene scene = planeScene(true);
  scene.lights.push_back(sunLight(0.0, 90.0, kWhiteEfficacyLmPerW));
  ProgressiveSolver solver(scene, meshScene(scene, 1.0 / 16), lightOptions());
  solver.step();
  const std::vector<double> e = directIrradiance(solver);
  int shadowed = 0, lit = 0, square = 0;
  for (size_t j = 0; j < e.size(); ++j) {
    const Vec3 c = solver.patches()[j].centroid;
    if (c.z > 0.25) {
      ++square;
      EXPECT_NEAR(e[j], 1.0, 1e-12);
      continue;
    }
    const bool under = c.x > 0.25 && c.x < 0.5 && c.y > 0.25 && c.y < 0.5;
    if (e[j] == 0.0) ++shadowed;
    if (std::abs(e[j] - 1.0) < 1e-12) ++lit;
    EXPECT_EQ(e[j] == 0.0, under) << "patch at (" << c.x << ", " << c.y << ")";
  }
  EXPECT_EQ(square, 16);
  EXPECT_EQ(shadowed, 16);
  EXPECT_EQ(lit, 256 - 16);
}

TEST(LightShot, BothBackEndsGiveTheSameFirstShot) {
  Scene scene = loadScene(test::dataPath("lights/three_lights.gltf").string());
  const std::vector<Patch> patches = meshScene(scene, 0.25);
  ProgressiveSolver native(scene, patches, lightOptions(Backend::Native));
  ProgressiveSolver mesh(scene, patches, lightOptions(Backend::Mesh));
  const Ledger a = native.step().ledger;
  const Ledger b = mesh.step().ledger;
  EXPECT_DOUBLE_EQ(a.emitted, b.emitted);
  EXPECT_NEAR(a.absorbed, b.absorbed, 1e-12 * a.emitted);
  EXPECT_NEAR(a.escaped, b.escaped, 1e-12 * a.emitted);
  for (size_t j = 0; j < patches.size(); ++j)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(native.radiosity()[j][c], mesh.radiosity()[j][c], 1e-12 * (1 + native.radiosity()[j][c]));
  for (int i = 0; i < 20; ++i) {
    EXPECT_LE(native.step().ledger.imbalance(), 1e-9);
    EXPECT_LE(mesh.step().ledger.imbalance(), 1e-9);
  }
}

}  // namespace
}  // namespace radmesh
