#include "solver/bake/display_radiosity.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "solver/meshing/meshing.h"

namespace radmesh {
namespace {

Scene greyRedScene(std::vector<std::vector<Vec3>> polygons, std::vector<int> materials = {}) {
  Scene s;
  s.source = "test";
  s.materials.push_back({"grey", Rgb(0.5), Rgb(1.0)});
  s.materials.push_back({"red", Rgb(0.6, 0.1, 0.1), Rgb(0.0)});
  for (size_t i = 0; i < polygons.size(); ++i)
    s.polygons.push_back({std::move(polygons[i]), materials.empty() ? 0 : materials[i], "test"});
  return s;
}

// Vertices of the mesh at a position, with their radiosity.
std::vector<double> valuesAt(const DisplayMesh& mesh, const std::vector<Rgb>& b, const Vec3& at) {
  std::vector<double> out;
  for (size_t v = 0; v < mesh.positions.size(); ++v)
    if (glm::length(mesh.positions[v] - at) < 1e-9) out.push_back(b[v].r);
  std::sort(out.begin(), out.end());
  return out;
}

// Two equal floor patches with B = 1 and B = 3: the shared edge's vertices show 2.
TEST(DisplayRadiosity, SharedEdgeAveragesEqualPatches) {
  const auto patches = meshScene(greyRedScene({{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}}}), 1.0);
  ASSERT_EQ(patches.size(), 2u);
  const DisplayMesh mesh = buildDisplayMesh(patches);
  EXPECT_EQ(mesh.positions.size(), 6u);
  EXPECT_EQ(mesh.indices.size(), 12u);
  EXPECT_EQ(mesh.patchOfTriangle.size(), 4u);
  std::vector<Rgb> patchB(2);
  patchB[patches[0].centroid.x < 1 ? 0 : 1] = Rgb(1.0);
  patchB[patches[0].centroid.x < 1 ? 1 : 0] = Rgb(3.0);
  const auto b = vertexRadiosity(mesh, patchB);
  EXPECT_EQ(valuesAt(mesh, b, {1, 0, 0}), std::vector<double>{2.0});
  EXPECT_EQ(valuesAt(mesh, b, {1, 1, 0}), std::vector<double>{2.0});
  EXPECT_EQ(valuesAt(mesh, b, {0, 0, 0}), std::vector<double>{1.0});
  EXPECT_EQ(valuesAt(mesh, b, {2, 1, 0}), std::vector<double>{3.0});
}

// Unequal areas: the larger patch speaks for more of the vertex.
TEST(DisplayRadiosity, AveragesByArea) {
  const auto patches = meshScene(greyRedScene({{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                                          {{1, 0, 0}, {1.25, 0, 0}, {1.25, 1, 0}, {1, 1, 0}}}),
                                 1.0);
  ASSERT_EQ(patches.size(), 2u);
  const DisplayMesh mesh = buildDisplayMesh(patches);
  std::vector<Rgb> patchB{Rgb(patches[0].areaM2 > 0.5 ? 1.0 : 5.0), Rgb(patches[1].areaM2 > 0.5 ? 1.0 : 5.0)};
  const auto b = vertexRadiosity(mesh, patchB);
  EXPECT_NEAR(valuesAt(mesh, b, {1, 0, 0}).at(0), (1.0 * 1.0 + 0.25 * 5.0) / 1.25, 1e-15);
}

// A floor meeting a wall, and two coplanar materials: corners there stay apart.
TEST(DisplayRadiosity, CreasesAndMaterialBoundariesAreNotAveraged) {
  const Scene crease = greyRedScene({{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},    // floor, +z
                                {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}}});  // wall, +y
  const auto patches = meshScene(crease, 1.0);
  ASSERT_EQ(patches.size(), 2u);
  const DisplayMesh mesh = buildDisplayMesh(patches);
  EXPECT_EQ(mesh.positions.size(), 8u);
  const auto b = vertexRadiosity(
      mesh, {Rgb(patches[0].polygon == 0 ? 1.0 : 3.0), Rgb(patches[1].polygon == 0 ? 1.0 : 3.0)});
  EXPECT_EQ(valuesAt(mesh, b, {0, 0, 0}), (std::vector<double>{1.0, 3.0}));
  EXPECT_EQ(valuesAt(mesh, b, {1, 0, 0}), (std::vector<double>{1.0, 3.0}));

  const Scene twoMaterials = greyRedScene(
      {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}}}, {0, 1});
  EXPECT_EQ(buildDisplayMesh(meshScene(twoMaterials, 1.0)).positions.size(), 8u);
}

// Two rooms' floors meeting under a wall of no thickness: the wall stands on the seam, so the dark
// room's floor is not averaged with the lit one's (it glowed along the wall in bakes and renders).
// A wall behind the floor (a window's reveal behind its wall) stands on nothing; without a wall, the
// seam averages as any.
TEST(DisplayRadiosity, AWallStandingOnASeamIsNotAveragedAcross) {
  const std::vector<Vec3> lit = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, dark = {{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}};
  const std::vector<Vec3> above = {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}};     // facing -x, standing on the seam
  const std::vector<Vec3> below = {{1, 0, -1}, {1, 1, -1}, {1, 1, 0}, {1, 0, 0}};   // the same plane, behind the floor
  for (const auto& [wall, apart] : {std::pair{above, true}, std::pair{below, false}}) {
    const Scene s = greyRedScene({lit, dark, wall});
    const auto patches = meshScene(s, 1.0);
    ASSERT_EQ(patches.size(), 3u);
    std::vector<Rgb> b(3);
    for (size_t p = 0; p < 3; ++p) b[p] = Rgb(patches[p].polygon == 0 ? 2.0 : 0.0);  // the wall dark too
    const DisplayMesh mesh = buildDisplayMesh(patches);
    const auto v = vertexRadiosity(mesh, b);
    // At the seam's ends: the wall's vertex, and the floors' one each or one averaged.
    const std::vector<double> expected = apart ? std::vector<double>{0.0, 0.0, 2.0} : std::vector<double>{0.0, 1.0};
    EXPECT_EQ(valuesAt(mesh, v, {1, 0, 0}), expected) << (apart ? "standing" : "behind");
    EXPECT_EQ(valuesAt(mesh, v, {1, 1, 0}), expected) << (apart ? "standing" : "behind");
  }
}

// A 4 x 4 grid of patches: 25 shared vertices, 32 triangles, counter-clockwise around the normal;
// the centre vertex averages the four patches around it.
TEST(DisplayRadiosity, GridWeldsIntoSharedVertices) {
  const auto patches = meshScene(greyRedScene({{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}}), 0.25);
  const DisplayMesh mesh = buildDisplayMesh(patches);
  EXPECT_EQ(mesh.positions.size(), 25u);
  EXPECT_EQ(mesh.indices.size(), 32u * 3);
  for (size_t t = 0; t < mesh.indices.size(); t += 3) {
    const Vec3 &a = mesh.positions[mesh.indices[t]], &b = mesh.positions[mesh.indices[t + 1]],
               &c = mesh.positions[mesh.indices[t + 2]];
    EXPECT_GT(glm::dot(glm::cross(b - a, c - a), Vec3(0, 0, 1)), 0.0);
  }
  std::vector<Rgb> patchB;
  for (const Patch& p : patches) patchB.push_back(Rgb(p.centroid.x + 10 * p.centroid.y));
  const auto b = vertexRadiosity(mesh, patchB);
  // The mean of the four cells around (0.5, 0.5) is the value at their common corner.
  EXPECT_NEAR(valuesAt(mesh, b, {0.5, 0.5, 0}).at(0), 0.5 + 10 * 0.5, 1e-12);
}

// Far from the origin, corners computed from two polygons still weld.
TEST(DisplayRadiosity, WeldsFarFromTheOrigin) {
  const double x = 1e5 + 0.3, y = -1e5 + 0.7;
  const auto patches =
      meshScene(greyRedScene({{{x, y, 5}, {x + 0.2, y, 5}, {x + 0.2, y + 0.2, 5}, {x, y + 0.2, 5}},
                         {{x + 0.2, y, 5}, {x + 0.3, y, 5}, {x + 0.3, y + 0.2, 5}, {x + 0.2, y + 0.2, 5}}}),
                1.0);
  ASSERT_EQ(patches.size(), 2u);
  EXPECT_EQ(buildDisplayMesh(patches).positions.size(), 6u);
}

TEST(DisplayRadiosity, RefusesRadiosityForTooFewPatches) {
  const auto patches = meshScene(greyRedScene({{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}}}), 1.0);
  EXPECT_THROW(vertexRadiosity(buildDisplayMesh(patches), {Rgb(1.0)}), std::invalid_argument);
}

}  // namespace
}  // namespace radmesh
