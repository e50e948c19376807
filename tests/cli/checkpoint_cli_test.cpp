// `radmesh solve --checkpoint / --resume` as a user runs them: a resumed bake is bitwise the
// straight one, and a checkpoint that does not fit is refused before anything is written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/cli/cli_run.h"

namespace radmesh {
namespace {

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The paper's cell, 47 patches: the default cell, chosen from the box's size, makes ~1700.
const std::string kOptions = "--quiet --resolution 64 --shooters 2 --until 1 --until-unshot 0 ";
const std::string kSolve = "solve cornell --cell 0.381 " + kOptions;

void expectResumedBakeIsTheStraightOne(const std::string& backend) {
  const std::string straight = tempPath("straight-" + backend + ".glb");
  const std::string resumed = tempPath("resumed-" + backend + ".glb");
  const std::string checkpoint = tempPath(backend + ".ckpt");
  const std::string solve = kSolve + "--backend " + backend + " ";
  CommandRun run = radmesh(solve + "--max-iterations 80 --out " + straight);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  run = radmesh(solve + "--max-iterations 40 --checkpoint " + checkpoint);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("wrote checkpoint " + checkpoint), std::string::npos) << run.output;
  run = radmesh(solve + "--max-iterations 80 --resume " + checkpoint + " --out " + resumed);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("resumed from " + checkpoint + " after iteration 40"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find(", 80 iterations,"), std::string::npos) << run.output;
  const std::string expected = readBytes(straight);
  ASSERT_GT(expected.size(), 1000u);
  EXPECT_TRUE(readBytes(resumed) == expected) << "the resumed bake differs from the straight one";
}

TEST(CliCheckpoint, ResumedBakeIsBitwiseTheStraightOneNative) { expectResumedBakeIsTheStraightOne("native"); }
TEST(CliCheckpoint, ResumedBakeIsBitwiseTheStraightOneMesh) { expectResumedBakeIsTheStraightOne("mesh"); }

TEST(CliCheckpoint, PeriodicCheckpointsLeaveOneGoodFile) {
  const std::string checkpoint = tempPath("every.ckpt");
  const CommandRun run = radmesh(kSolve + "--max-iterations 20 --checkpoint " + checkpoint + " --checkpoint-every 0.001");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(checkpoint).parent_path())) {
    EXPECT_EQ(entry.path().filename(), "every.ckpt");
    ++files;
  }
  EXPECT_EQ(files, 1);
  const CommandRun resumed = radmesh(kSolve + "--max-iterations 20 --resume " + checkpoint);
  ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("after iteration 20"), std::string::npos) << resumed.output;
}

// A refused resume exits 2 naming the file and what differs, and writes none of its outputs.
void expectRefused(const std::string& arguments, const std::string& checkpoint, const std::string& says) {
  const std::string out = tempPath("refused.glb");
  const std::string stats = tempPath("refused.json");
  const CommandRun run = radmesh(arguments + " --resume " + checkpoint + " --out " + out + " --stats " + stats);
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find(checkpoint), std::string::npos) << run.output;
  EXPECT_NE(run.output.find(says), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("fix:"), std::string::npos) << run.output;
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_FALSE(std::filesystem::exists(stats));
}

TEST(CliCheckpoint, RefusesACheckpointThatDoesNotFit) {
  const std::string checkpoint = tempPath("cornell.ckpt");
  const CommandRun run = radmesh(kSolve + "--max-iterations 5 --checkpoint " + checkpoint);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const std::string good = readBytes(checkpoint);
  expectRefused("solve furnace --quiet --resolution 64 --shooters 2", checkpoint, "another meshed scene");
  expectRefused("solve cornell --cell 0.2 " + kOptions, checkpoint, "another meshed scene");
  expectRefused(kSolve + "--ratio 2", checkpoint, "--ratio 3 there, 2 here");

  std::ofstream(checkpoint, std::ios::binary) << good.substr(0, good.size() / 2);
  expectRefused(kSolve, checkpoint, "is truncated");
  std::string flipped = good;
  flipped[good.size() / 2] = static_cast<char>(flipped[good.size() / 2] ^ 1);
  std::ofstream(checkpoint, std::ios::binary) << flipped;
  expectRefused(kSolve, checkpoint, "is corrupted");
  expectRefused(kSolve, tempPath("missing.ckpt"), "cannot be read");
}

TEST(CliCheckpoint, CheckpointEveryNeedsACheckpointFile) {
  const CommandRun run = radmesh(kSolve + "--max-iterations 2 --checkpoint-every 5");
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.output.find("--checkpoint"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace radmesh
