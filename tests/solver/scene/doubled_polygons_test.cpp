#include "solver/scene/doubled_polygons.h"

#include <gtest/gtest.h>

namespace radmesh {
namespace {

Scene squares() {
  Scene scene;
  scene.materials = {{"white", Rgb(0.5), Rgb(0.0)}, {"red", Rgb(0.5, 0.1, 0.1), Rgb(0.0)}};
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{1, 1, 0}, d{0, 1, 0};
  scene.polygons = {{{a, b, c, d}, 0, "line 10: f"},
                    {{c, d, a, b}, 0, "line 11: f"},   // the same face from another corner: dropped
                    {{d, c, b, a}, 0, "line 12: f"},   // its other side: kept
                    {{a, b, c, d}, 1, "line 13: f"},   // another material: kept
                    {{a, b, c}, 0, "line 14: f"},      // part of it: kept
                    {{a, b, c, d}, 0, "line 15: f"}};  // dropped
  return scene;
}

TEST(DoubledPolygons, ExactCopiesOfAFaceAreDroppedAndTheFirstIsKept) {
  Scene scene = squares();
  const DoubledPolygons doubled = dropDoubledPolygons(scene);
  EXPECT_EQ(doubled.dropped, 2u);
  EXPECT_EQ(doubled.first, "polygon 1 (line 11: f)");
  ASSERT_EQ(scene.polygons.size(), 4u);
  const char* kept[] = {"line 10: f", "line 12: f", "line 13: f", "line 14: f"};
  for (int k = 0; k < 4; ++k) EXPECT_EQ(scene.polygons[k].origin, kept[k]);
}

TEST(DoubledPolygons, AFaceListedOnceIsLeftAlone) {
  Scene scene = squares();
  scene.polygons.erase(scene.polygons.begin() + 5);
  scene.polygons.erase(scene.polygons.begin() + 1);
  EXPECT_EQ(dropDoubledPolygons(scene).dropped, 0u);
  EXPECT_EQ(scene.polygons.size(), 4u);
}

}  // namespace
}  // namespace radmesh
