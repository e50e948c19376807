// Streaming: frames of the office drawn from the solver thread's snapshots after 1, 10 and 100
// iterations hold more and more light (progressive shooting only ever adds radiosity; the
// display-only ambient term is off so that nothing estimated is added).
#include <gtest/gtest.h>

#include <chrono>

#include "solver/io/scene_loader.h"
#include "tests/viewer/image_compare.h"
#include "tests/viewer/solver_thread_wait.h"
#include "viewer/camera.h"
#include "viewer/exposure.h"
#include "viewer/offscreen_render.h"
#include "viewer/solver_thread.h"

namespace radmesh {
namespace {

test::Snapshot snapshotAt(SolverThread& thread, int iteration) {
  thread.step(iteration - thread.latest()->iteration());
  return test::waitFor(
      thread, [&](const SolverSnapshot& s) { return s.iteration() >= iteration || !s.error.empty(); },
      std::chrono::minutes(5));
}

TEST(Streaming, FramesAtIterations1_10_100GrowInTotalLight) {
  const Scene scene = loadScene("office");
  const RenderView view = WalkCamera(sceneFrame(scene)).view();
  SolveSetup setup;
  setup.options.ambient = false;
  setup.options.until = 1.0;
  SolverThread thread(scene, setup, /*playing=*/false);
  ASSERT_EQ(test::waitFor(thread, [](const SolverSnapshot& s) { return s.mesh || !s.error.empty(); })->error, "");

  std::vector<test::Snapshot> snapshots;
  for (int iteration : {1, 10, 100}) {
    snapshots.push_back(snapshotAt(thread, iteration));
    ASSERT_EQ(snapshots.back()->iteration(), iteration) << snapshots.back()->error;
  }
  // One exposure for all three (the last frame's, halved so little clips): light is comparable.
  OffscreenShading shading;
  shading.exposure = 0.5 * autoExposure(*snapshots.back()->mesh, snapshots.back()->vertexB);
  OffscreenRenderer renderer(*snapshots.back()->mesh, {320, 240});
  std::vector<double> light;
  for (const auto& s : snapshots) light.push_back(test::totalLinearLight(renderer.render(s->vertexB, view, shading)));
  EXPECT_GT(light[0], 0.0);
  EXPECT_GT(light[1], 1.01 * light[0]);
  EXPECT_GT(light[2], 1.01 * light[1]);
}

}  // namespace
}  // namespace radmesh
