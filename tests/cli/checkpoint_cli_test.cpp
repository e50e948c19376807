// `radmesh solve --checkpoint / --resume` as a user runs them: a resumed bake is bitwise the
// straight one, and a checkpoint that does not fit is refused before anything is written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "tests/cli/cli_run.h"

namespace radmesh {
namespace {

// The paper's cell, 47 patches: the default cell, chosen from the box's size, makes ~1700.
const std::string kOptions = "--quiet --resolution 64 --shooters 2 --until 1 --until-unshot 0 ";
const std::string kSolve = "solve cornell --cell 0.381 " + kOptions;

// The stats but the wall times, which no two runs share.
nlohmann::json withoutSeconds(nlohmann::json stats) {
  if (stats.is_object()) {
    stats.erase("seconds");
    stats.erase("host_seconds");
    for (auto& [key, value] : stats.items()) value = withoutSeconds(value);
  } else if (stats.is_array()) {
    for (auto& value : stats) value = withoutSeconds(value);
  }
  return stats;
}

// `solve` to `total` iterations straight, and stopped at `first` with a checkpoint then resumed:
// the same bake, bitwise, and the same stats but the times. Returns the resumed run's output.
std::string expectResumedRunIsTheStraightOne(const std::string& solve, int first, int total,
                                             const std::string& name) {
  const std::string straight = tempPath("straight-" + name + ".glb"), resumed = tempPath("resumed-" + name + ".glb");
  const std::string straightStats = tempPath("straight-" + name + ".json");
  const std::string resumedStats = tempPath("resumed-" + name + ".json");
  const std::string checkpoint = tempPath(name + ".ckpt");
  const std::string to = " --max-iterations " + std::to_string(total);
  CommandRun run = radmesh(solve + to + " --out " + straight + " --stats " + straightStats);
  EXPECT_EQ(run.exitCode, 0) << run.output;
  run = radmesh(solve + " --max-iterations " + std::to_string(first) + " --checkpoint " + checkpoint);
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("wrote checkpoint " + checkpoint), std::string::npos) << run.output;
  run = radmesh(solve + to + " --resume " + checkpoint + " --out " + resumed + " --stats " + resumedStats);
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("resumed from " + checkpoint), std::string::npos) << run.output;
  const std::string expected = readBytes(straight);
  EXPECT_GT(expected.size(), 1000u);
  EXPECT_TRUE(readBytes(resumed) == expected) << "the resumed bake differs from the straight one";
  nlohmann::json a = nlohmann::json::parse(readBytes(straightStats), nullptr, false);
  nlohmann::json b = nlohmann::json::parse(readBytes(resumedStats), nullptr, false);
  EXPECT_FALSE(a.is_discarded());
  // The resumed run's "seconds" are its own, after the iterations the checkpoint brought.
  EXPECT_EQ(a.value("resumed_after_iterations", -1), 0);
  const int resumedAfter = b.value("resumed_after_iterations", -1);
  EXPECT_GE(resumedAfter, first);  // a cells solve stops at the end of a round
  EXPECT_LT(resumedAfter, total);
  EXPECT_TRUE(run.output.find("after iteration " + std::to_string(resumedAfter) + "\n") != std::string::npos ||
              run.output.find("(" + std::to_string(resumedAfter) + " iterations)") != std::string::npos)
      << run.output;
  a.erase("resumed_after_iterations"), b.erase("resumed_after_iterations");
  EXPECT_EQ(withoutSeconds(b).dump(), withoutSeconds(a).dump());
  return run.output;
}

void expectResumedBakeIsTheStraightOne(const std::string& backend) {
  const std::string output = expectResumedRunIsTheStraightOne(kSolve + "--backend " + backend, 40, 80, backend);
  EXPECT_NE(output.find("after iteration 40"), std::string::npos) << output;
  EXPECT_NE(output.find(", 80 iterations (40 after the checkpoint's 40),"), std::string::npos) << output;  // its it/s: of 40
}

TEST(CliCheckpoint, ResumedBakeIsBitwiseTheStraightOneNative) { expectResumedBakeIsTheStraightOne("native"); }
TEST(CliCheckpoint, ResumedBakeIsBitwiseTheStraightOneMesh) { expectResumedBakeIsTheStraightOne("mesh"); }

// Elements: uniform ones, and the adaptive tree split on after the stop.
TEST(CliCheckpoint, ResumedBakeIsBitwiseTheStraightOneWithUniformElements) {
  expectResumedRunIsTheStraightOne(kSolve + "--subdivide uniform --min-element 0.2", 20, 40, "uniform");
}
TEST(CliCheckpoint, ResumedBakeIsBitwiseTheStraightOneWithAdaptiveElements) {
  const std::string output = expectResumedRunIsTheStraightOne(
      kSolve + "--subdivide adaptive --min-element 0.05 --split-contrast 0.2", 8, 16, "adaptive");
  EXPECT_NE(output.find("after iteration 8"), std::string::npos) << output;
}

// A --checkpoint no file can be written to is an option error (exit 2), named as --out's are, before
// the scene is read (it exited 1 naming a temporary file beside it).
TEST(CliCheckpoint, ACheckpointPathThatCannotBeWrittenIsRefusedFirst) {
  const std::string folder = tempPath("folder");
  std::filesystem::create_directories(folder);
  for (const auto& [path, says] :
       {std::pair{tempPath("missing/x.ckpt"), "the folder '" + tempPath("missing") + "' does not exist"},
        std::pair{folder, "--checkpoint '" + folder + "' is a folder"}})
    for (const std::string cells : {"off", "auto"}) {
      const CommandRun run = radmesh("solve two-rooms --cells " + cells + " --checkpoint " + path);
      EXPECT_EQ(run.exitCode, 2) << run.output;
      EXPECT_EQ(run.output.find("radmesh: error: --checkpoint '" + path + "'"), 0u) << run.output;
      EXPECT_NE(run.output.find(says), std::string::npos) << run.output;
    }
}


// Ctrl-C stops a solve at the end of the iteration under way: its checkpoint is written and said,
// no bake or stats of a solve cut short, exit 130; without --checkpoint the loss is said.
TEST(CliCheckpoint, CtrlCWritesTheCheckpointAndSaysWhere) {
  const std::string saved = tempPath("interrupted.ckpt"), bake = tempPath("interrupted.glb");
  const std::string radmeshPath = (test::binaryDir() / "cli" / "radmesh").string();
  for (const std::string cells : {"off", "auto"}) {
    std::filesystem::remove(saved);
    const CommandRun run = runCommand("(" + radmeshPath + " solve two-rooms --cell 0.1 --cells " + cells +
                                      " --quiet --checkpoint " + saved + " --out " + bake +
                                      " & pid=$!; sleep 2; kill -INT $pid; wait $pid; echo exit $?)");
    EXPECT_NE(run.output.find("exit 130"), std::string::npos) << cells << ": " << run.output;
    EXPECT_NE(run.output.find(": the checkpoint " + saved + " holds the work; go on with --resume " + saved),
              std::string::npos)
        << cells << ": " << run.output;
    EXPECT_FALSE(std::filesystem::exists(bake)) << cells;
    const CommandRun resumed =
        radmesh("solve two-rooms --cell 0.1 --cells " + cells + " --quiet --max-iterations 1 --resume " + saved);
    EXPECT_EQ(resumed.exitCode, 0) << cells << ": " << resumed.output;
  }
  const CommandRun lost = runCommand("(" + radmeshPath + " solve two-rooms --cell 0.1 --quiet & pid=$!; sleep 2; " +
                                     "kill -INT $pid; wait $pid; echo exit $?)");
  EXPECT_NE(lost.output.find("nothing saved (give --checkpoint FILE to keep a solve's work)"), std::string::npos)
      << lost.output;
  EXPECT_NE(lost.output.find("exit 130"), std::string::npos) << lost.output;
}

// --max-iterations counts from the start: a resume already past it solves nothing, and says so.
TEST(CliCheckpoint, AResumePastMaxIterationsSaysNothingMoreWasSolved) {
  const std::string saved = tempPath("c15.ckpt");
  ASSERT_EQ(radmesh("solve cornell --cell 0.1 --resolution 16 --max-iterations 15 --checkpoint " + saved).exitCode, 0);
  CommandRun run = radmesh("solve cornell --cell 0.1 --resolution 16 --max-iterations 10 --resume " + saved);
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("15 iterations (0 after the checkpoint's 15)"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("radmesh: warning: the checkpoint already holds 15 iterations, at or past "
                            "--max-iterations 10 (which counts from the start of the solve): nothing more was solved; "
                            "give --max-iterations above 15 to go on"),
            std::string::npos)
      << run.output;
  run = radmesh("solve cornell --cell 0.1 --resolution 16 --max-iterations 16 --resume " + saved);
  EXPECT_EQ(run.output.find("already holds"), std::string::npos) << run.output;
}

// A checkpoint has no extension to check, so the file already at its path is: a scene's included
// file (or any file not a checkpoint) is refused, not replaced. A link to a checkpoint stays a link,
// its checkpoint replaced.
TEST(CliCheckpoint, AFileThatIsNotACheckpointIsNotReplacedAndALinkStaysALink) {
  const std::string part = tempPath("part.mgf"), main = tempPath("main.mgf");
  std::filesystem::copy_file(test::dataPath("daylight/room_one_window.mgf"), part);
  { std::ofstream(main) << "i part.mgf\n"; }
  const std::string before = readBytes(part);
  CommandRun run = radmesh("solve " + main + " --sky 10000 --max-iterations 2 --checkpoint " + part);
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("radmesh: error: --checkpoint '" + part + "' is a file that is not a radmesh checkpoint: "
                            "writing the checkpoint would replace it; give a new path, or a checkpoint's"),
            std::string::npos)
      << run.output;
  EXPECT_EQ(readBytes(part), before);

  const std::string saved = tempPath("saved.ckpt"), link = tempPath("link.ckpt");
  ASSERT_EQ(radmesh("solve cornell --cell 0.1 --resolution 16 --max-iterations 2 --checkpoint " + saved).exitCode, 0);
  const std::string two = readBytes(saved);
  std::filesystem::create_symlink(saved, link);
  run = radmesh("solve cornell --cell 0.1 --resolution 16 --max-iterations 3 --checkpoint " + link);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  EXPECT_NE(readBytes(saved), two);  // the checkpoint it leads to is the new one
}
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
  expectRefused(kSolve + "--projection plane --ratio 2", checkpoint, "--ratio 3 there, 2 here");
  expectRefused(kSolve + "--subdivide uniform", checkpoint, "--subdivide off there, uniform here");

  std::ofstream(checkpoint, std::ios::binary) << good.substr(0, good.size() / 2);
  expectRefused(kSolve, checkpoint, "is truncated");
  std::string flipped = good;
  flipped[good.size() / 2] = static_cast<char>(flipped[good.size() / 2] ^ 1);
  std::ofstream(checkpoint, std::ios::binary) << flipped;
  expectRefused(kSolve, checkpoint, "is corrupted");
  expectRefused(kSolve, tempPath("missing.ckpt"), "cannot be read");
  std::string older = good;  // before the ledger kept the lights' part on back faces
  older[8] = 3;
  std::ofstream(checkpoint, std::ios::binary) << older;
  expectRefused(kSolve, checkpoint, "is a version 3 checkpoint (or its header is damaged); this radmesh reads version 4");
}

// Two rooms, each a cell, the light through the door kept by direction bin; about 30 rounds.
const std::string kCells = "solve two-rooms --cells auto --cell 0.75 --resolution 32 --until-unshot 0.02 --quiet";

TEST(CliCheckpoint, CellsResumedBakeIsBitwiseTheStraightOne) {
  const std::string output = expectResumedRunIsTheStraightOne(kCells, 150, 1000000, "cells");
  EXPECT_NE(output.find("after round "), std::string::npos) << output;
}

TEST(CliCheckpoint, CellsRefuseACheckpointOfOtherCellsOrOfOneSolve) {
  const std::string cells = tempPath("cells.ckpt"), one = tempPath("one.ckpt");
  CommandRun run = radmesh(kCells + " --max-iterations 50 --checkpoint " + cells);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const std::string whole = "solve two-rooms --cell 0.75 --resolution 32 --until 1 --until-unshot 0.02 --quiet";
  run = radmesh(whole + " --max-iterations 5 --checkpoint " + one);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  expectRefused(kCells + " --exchange-shots 8", cells, "--exchange-shots 16 there, 8 here");
  expectRefused(kCells + " --portal-bins 2", cells, "--portal-bins 4 there, 2 here");
  expectRefused("solve two-rooms --cells auto --cell 0.5 --resolution 32 --until-unshot 0.02 --quiet", cells,
                "another meshed scene");
  expectRefused(whole, cells, "is a checkpoint of a cells solve (--cells auto), not of one solve");
  expectRefused(kCells, one, "is a checkpoint of one solve (--cells off), not of a cells solve");
}

TEST(CliCheckpoint, RefusesOtherSubdivideOptionsNamingThem) {
  const std::string adaptive = kSolve + "--subdivide adaptive --min-element 0.05";
  const std::string checkpoint = tempPath("adaptive.ckpt");
  const CommandRun run = radmesh(adaptive + " --max-iterations 3 --checkpoint " + checkpoint);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  expectRefused(adaptive + " --split-contrast 0.3", checkpoint, "--split-contrast 0.1 there, 0.3 here");
  expectRefused(kSolve + "--subdivide adaptive --min-element 0.1", checkpoint, "--min-element 0.05 there, 0.1 here");
  expectRefused(kSolve + "--subdivide uniform --min-element 0.05", checkpoint, "--subdivide adaptive there, uniform here");
  expectRefused(kSolve, checkpoint, "--subdivide adaptive there, off here");
}

// Options that differ exactly as a preset's are refused with that preset as the fix; the back end
// too where it differs; other options with the general fix.
TEST(CliCheckpoint, NamesThePresetItWasWrittenWith) {
  const std::string checkpoint = tempPath("bake.ckpt");
  const std::string solve = "solve cornell --cell 0.381 --quiet ";
  ASSERT_EQ(radmesh(solve + "--max-iterations 2 --checkpoint " + checkpoint).exitCode, 0);
  const std::string differ = ": was written with other options: --projection hemicube there, plane here; --resolution "
                             "256 there, 128 here";
  expectRefused(solve + "--preset paper", checkpoint,
                differ + " (fix: resume with the options it was written with (--preset bake), or solve from scratch "
                         "without --resume)");
  expectRefused(solve + "--preset paper --backend mesh", checkpoint,
                "(fix: resume with the options it was written with (--preset bake, on the native back end), or solve "
                "from scratch without --resume)");
  expectRefused(solve + "--resolution 128", checkpoint,
                ": was written with other options: --resolution 256 there, 128 here (fix: resume with the options it "
                "was written with (--preset bake), or solve from scratch without --resume)");
  // Written with no preset's options: the general fix.
  ASSERT_EQ(radmesh(solve + "--max-iterations 2 --resolution 64 --checkpoint " + checkpoint).exitCode, 0);
  expectRefused(solve, checkpoint,
                ": was written with other options: --resolution 64 there, 256 here (fix: resume with the options it "
                "was written with, or solve from scratch without --resume)");
}

TEST(CliCheckpoint, CheckpointEveryNeedsACheckpointFile) {
  const CommandRun run = radmesh(kSolve + "--max-iterations 2 --checkpoint-every 5");
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.output.find("--checkpoint"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace radmesh
