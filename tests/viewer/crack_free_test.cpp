// A display mesh without cracks: inside a closed room, every pixel shows a surface. Patches of
// different sizes meet all over the office cut into elements (a patch clipped by its polygon gets
// fewer elements than a whole one beside it), so corners lie inside the edges of neighbours
// (T-vertices); drawn unresolved, pixels between the long edge and the short ones show the
// background. Before buildDisplayMesh resolved them, these four views showed 2, 0, 1 and 1
// background pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "solver/io/scene_loader.h"
#include "solver/meshing/elements.h"
#include "solver/meshing/meshing.h"
#include "viewer/camera.h"
#include "viewer/offscreen_render.h"
#include "viewer/renderer.h"

namespace radmesh {
namespace {

TEST(CrackFree, NoBackgroundShowsInsideTheClosedOfficeCutIntoElements) {
  const Scene scene = loadScene("office");  // closed: door and windows are recesses with leaves and glass
  const Elements elements = subdivideUniform(meshScene(scene, kDefaultCellM), 0.05);
  ASSERT_GT(elements.elements.size(), 90'000u);
  const DisplayMesh mesh = buildDisplayMesh(elements.elements);
  // Radiosity 1 everywhere: every surface the same mid grey, far from the clear colour.
  const std::vector<Rgb> vertexB(mesh.positions.size(), Rgb(1.0));
  OffscreenRenderer renderer(mesh, {1600, 1000});
  RenderView view = WalkCamera(sceneFrame(scene)).view();
  EXPECT_EQ(backgroundPixels(renderer.render(vertexB, view, {0.2, {}})), 0) << "the start view";
  view.eye = {3.6, 2.7, 1.2};
  for (const glm::dvec3 look : {glm::dvec3{0.0, 0.0, 0.0}, glm::dvec3{7.2, 5.4, 2.7}, glm::dvec3{7.2, 0.0, 0.5}}) {
    view.look = look;
    EXPECT_EQ(backgroundPixels(renderer.render(vertexB, view, {0.2, {}})), 0)
        << "from (3.6, 2.7, 1.2) towards (" << look.x << ", " << look.y << ", " << look.z << ")";
  }
}

}  // namespace
}  // namespace radmesh
