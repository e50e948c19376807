#include "solver/radiosity/accuracy.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "tests/solver/patch_fixtures.h"

namespace radmesh {
namespace {

// A lamp (E = 100) and a wall twice its area reflecting 0.4 of what reaches it.
struct LampAndWall {
  Scene scene;
  std::vector<Patch> patches;
  LampAndWall() {
    scene.materials = {test::grey(0.0, 100.0, "lamp"), test::grey(0.5, 0.0, "wall")};
    patches.push_back(test::makePatch({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, 0, 0));
    patches.push_back(test::makePatch({{0, 0, 1}, {0, 2, 1}, {1, 2, 1}, {1, 0, 1}}, 1, 1));
  }
};

TEST(Accuracy, ErrorIsOfTheReflectedLightNotTheGivenEmission) {
  const LampAndWall s;
  const std::vector<Rgb> reference = {Rgb(100.0), Rgb(0.4)};
  EXPECT_EQ(relativeRmsError(s.scene, s.patches, reference, reference), 0.0);
  // The wall 10 % too bright: 10 % error, however bright the lamp (with the lamp in the norm, 0.04 %).
  EXPECT_NEAR(relativeRmsError(s.scene, s.patches, {Rgb(100.0), Rgb(0.44)}, reference), 0.1, 1e-12);
  // One channel off by 0.12 of the three: sqrt(0.12^2 / (3 x 0.4^2)) = 0.1732.
  EXPECT_NEAR(relativeRmsError(s.scene, s.patches, {Rgb(100.0), Rgb(0.52, 0.4, 0.4)}, reference), 0.17320508, 1e-8);
}

TEST(Accuracy, RefusesOtherMeshesAndReferencesThatReflectNothing) {
  const LampAndWall s;
  EXPECT_THROW(relativeRmsError(s.scene, s.patches, {Rgb(1.0)}, {Rgb(100.0), Rgb(0.4)}), std::invalid_argument);
  EXPECT_THROW(relativeRmsError(s.scene, s.patches, {Rgb(100.0), Rgb(0.0)}, {Rgb(100.0), Rgb(0.0)}),
               std::invalid_argument);
}

}  // namespace
}  // namespace radmesh
