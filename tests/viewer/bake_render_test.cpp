// A bake is written y-up and keeps its scene's start view: the scene and its bake, each drawn from
// its own start view, make the same picture; a bake left in the scene's z-up axes would not.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "solver/bake/bake_reader.h"
#include "solver/bake/gltf_export.h"
#include "solver/io/scene_loader.h"
#include "solver/meshing/meshing.h"
#include "solver/radiosity/progressive_solver.h"
#include "tests/test_paths.h"
#include "tests/viewer/image_compare.h"
#include "viewer/camera.h"
#include "viewer/offscreen_render.h"

namespace radmesh {
namespace {

constexpr glm::ivec2 kSize{240, 180};

Image renderFromStart(const Scene& geometry, const DisplayMesh& mesh, const std::vector<Rgb>& vertexB,
                      double exposure) {
  OffscreenRenderer renderer(mesh, kSize);
  return renderer.render(vertexB, WalkCamera(sceneFrame(geometry)).view(), {exposure, {}});
}

Image renderBake(const std::string& path, double exposure) {
  const std::optional<Bake> bake = readBake(path);
  EXPECT_TRUE(bake.has_value()) << path;
  return renderFromStart(bakeScene(*bake, path), bake->mesh, bake->vertexB, exposure);
}

TEST(BakeUpAxis, TheZUpSceneAndItsYUpBakeRenderAlikeFromTheirStartViews) {
  const Scene scene = loadScene("two-rooms");  // z-up and closed: the walk starts inside, at a corner
  ASSERT_EQ(scene.upAxis, 2);
  SolveOptions options;
  options.resolution = 64;
  ProgressiveSolver solver(scene, meshScene(scene, 0.5), options);
  for (int i = 0; i < 40; ++i) solver.step();
  const DisplayMesh mesh = buildDisplayMesh(solver.patches());
  const std::vector<Rgb> vertexB = vertexRadiosity(mesh, solver.displayRadiosity());
  // White at the bake's colour unit: what the bake saturates is white in both pictures.
  const double exposure = 1.0 / bakeRadiosityPerColorUnit(vertexB);
  const Image sceneImage = renderFromStart(scene, mesh, vertexB, exposure);

  const std::filesystem::path dir = test::binaryDir() / "bake-up-axis";
  std::filesystem::create_directories(dir);
  const std::string turned = (dir / "two-rooms.glb").string();
  writeBakeGlb(turned, mesh, vertexB, scene.upAxis);
  const Image bakeImage = renderBake(turned, exposure);
  const test::ImageDifference same = test::compareImages(bakeImage, sceneImage);

  // The same bake left in the scene's axes, its geometry z-up while glTF (and the reader) take y.
  const std::string leftZUp = (dir / "two-rooms-left-z-up.glb").string();
  writeBakeGlb(leftZUp, mesh, vertexB, /*sceneUpAxis=*/1);
  const test::ImageDifference sideways = test::compareImages(renderBake(leftZUp, exposure), sceneImage);
  writePng(sceneImage, (dir / "scene.png").string());
  writePng(bakeImage, (dir / "bake.png").string());
  writePng(renderBake(leftZUp, exposure), (dir / "bake-left-z-up.png").string());

  // Float32 positions and colours stand between the two pictures, and the edges they move: within
  // the golden images' bound (40 dB, an RMSE of 2.55 levels), which rendering round-off keeps.
  EXPECT_LT(same.rmse, 2.55) << "PSNR " << same.psnrDb << " dB; pictures in " << dir;
  EXPECT_GT(sideways.rmse, 20.0) << "a bake left z-up would be seen lying on its side";
  std::printf("scene against bake: RMSE %.3f levels (%.1f dB); against a bake left z-up: RMSE %.1f levels\n", same.rmse,
              same.psnrDb, sideways.rmse);
}

}  // namespace
}  // namespace radmesh
