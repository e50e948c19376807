// A GLB's container version as radmesh names it: 1 was glTF 1.0's binary format, 2 is glTF 2.0's,
// and any other is none that exists (version 3 was called glTF 1.0's).
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "tests/cli/cli_run.h"
#include "tests/solver/io/gltf_test_file.h"

namespace radmesh {
namespace {

TEST(GlbContainerCli, AVersionThatDoesNotExistIsNotCalledGltfOnes) {
  test::GltfBuilder b;
  b.addTriangles("t", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, -1);
  for (const auto& [version, says] : {std::pair<int, std::string>{1, "glTF 1.0's binary format"},
                                      {3, "a GLB version that does not exist (2 is glTF 2.0's, 1 was glTF 1.0's)"}}) {
    const std::string glb = tempPath(std::to_string(version) + ".glb");
    std::ofstream(glb, std::ios::binary) << test::glbContainer(b.doc().dump(), version);
    const CommandRun run = radmesh("info " + glb);
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_EQ(run.output, "radmesh: error: " + glb + ": GLB container: its header says version " +
                              std::to_string(version) + ", not 2: " + says +
                              ", which radmesh does not read (fix: re-export the model as glTF 2.0)\n");
  }
}

}  // namespace
}  // namespace radmesh
