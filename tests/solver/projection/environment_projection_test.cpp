// The environment projection kept across shots, and freed between them (a cells solve's cells).
#include "solver/projection/environment_projection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "solver/io/builtin_scenes.h"
#include "solver/meshing/meshing.h"
#include "solver/projection/hemicube.h"

namespace radmesh {
namespace {

struct Shot {
  std::vector<double> formFactors;
  std::vector<long long> covered, shown;
  std::vector<std::vector<int>> items;
  bool operator==(const Shot&) const = default;
};

Shot shoot(EnvironmentProjection& projection, int shooter) {
  projection.project(shooter);
  Shot shot{projection.pixelFormFactors(), projection.coveredPixels(), projection.shownPixels(), {}};
  for (const ItemBuffer& buffer : projection.itemBuffers()) shot.items.push_back(buffer.items);
  return shot;
}

// Released, its item buffers and set-ups are gone; the next shot makes them again, and every
// figure of it is the one a projection that kept them gives, to the bit.
TEST(EnvironmentProjection, AProjectionWhoseScratchWasReleasedShootsTheSameBits) {
  const std::vector<Patch> patches = meshScene(builtinScene("office"), 1.0);
  ThreadPool pool(2);
  const double nearDepth = sceneNearDepth(patches);
  EnvironmentProjection kept(patches, makeHemicube(64), nearDepth, pool);
  EnvironmentProjection released(patches, makeHemicube(64), nearDepth, pool);
  for (int shooter : {0, 17, 400}) {
    const Shot expected = shoot(kept, shooter);
    released.releaseScratch();
    EXPECT_TRUE(released.itemBuffers().empty());
    const Shot again = shoot(released, shooter);
    EXPECT_GT(std::count_if(again.formFactors.begin(), again.formFactors.end(), [](double f) { return f > 0.0; }), 10);
    EXPECT_TRUE(again == expected) << "shooter " << shooter;
  }
}

}  // namespace
}  // namespace radmesh
