#include "solver/scene/scene.h"

#include <gtest/gtest.h>

#include "solver/scene/scene_error.h"

namespace radmesh {
namespace {

Scene unitSquareScene() {
  Scene s;
  s.source = "test";
  s.materials.push_back({"light", Rgb(0.5), Rgb(1.0, 2.0, 3.0)});
  s.polygons.push_back({{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}}, 0, "square"});
  return s;
}

TEST(Scene, AreaAndPowerOfARectangle) {
  const Scene s = unitSquareScene();
  EXPECT_DOUBLE_EQ(polygonArea(s.polygons[0].vertices), 2.0);
  EXPECT_DOUBLE_EQ(emittedPowerW(s), 2.0 * 6.0);
  EXPECT_NO_THROW(validateScene(s));
}

TEST(Scene, RefusesNaNNonPlanarZeroAreaAndNoEmitter) {
  Scene nan = unitSquareScene();
  nan.polygons[0].vertices[1].y = std::nan("");
  EXPECT_THROW(validateScene(nan), SceneError);

  Scene bent = unitSquareScene();
  bent.polygons[0].vertices[2].z = 0.2;
  EXPECT_THROW(validateScene(bent), SceneError);

  Scene flat = unitSquareScene();
  flat.polygons[0].vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  EXPECT_THROW(validateScene(flat), SceneError);

  Scene dark = unitSquareScene();
  dark.materials[0].emittance = Rgb(0.0);
  EXPECT_THROW(validateScene(dark), SceneError);

  Scene mirror = unitSquareScene();
  mirror.materials[0].rho = Rgb(1.0);
  EXPECT_THROW(validateScene(mirror), SceneError);
}

}  // namespace
}  // namespace radmesh
