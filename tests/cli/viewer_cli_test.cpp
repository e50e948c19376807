// radmesh-view from its command line, as a user runs it: what it refuses before a window opens,
// and how its smoke-test and frame-report runs end.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli/solve_flags.h"
#include "tests/cli/cli_run.h"
#include "viewer/image.h"

namespace radmesh {
namespace {

std::string viewerPath() { return (test::binaryDir() / "viewer" / "radmesh-view").string(); }

// The viewer's virtual display, or empty where it cannot run.
std::string xvfb() { return std::filesystem::exists(viewerPath()) ? virtualDisplay() : ""; }

// The viewer in a virtual display, or empty where it cannot run.
std::string windowed() {
  const std::string display = xvfb();
  return display.empty() ? "" : "timeout 120 " + display + viewerPath() + " ";
}

// --exchange-shots is one option wherever the cells solve runs: one help (four had told it four ways,
// "per cell per round" and "the camera's cell's iterations" among them).
TEST(ViewerCli, ExchangeShotsHasOneHelpOnEveryCommand) {
  std::vector<CommandRun> helps = {radmesh("solve --help"), radmesh("bench solve --help"),
                                   radmesh("bench cells --help")};
  if (std::filesystem::exists(viewerPath())) helps.push_back(runCommand(viewerPath() + " --help"));
  for (const CommandRun& help : helps) {
    EXPECT_EQ(help.exitCode, 0) << help.output;
    const std::string option = "--exchange-shots INT:POSITIVE=16";
    const size_t at = help.output.find(option);
    ASSERT_NE(at, std::string::npos) << help.output;
    const size_t text = help.output.find_first_not_of(" \n", at + option.size());
    EXPECT_EQ(help.output.substr(text, help.output.find('\n', text) - text), cli::kExchangeShotsHelp) << help.output;
  }
}

// The viewer's usage errors are worded as radmesh's (Cli.UsageErrorsNameTheWordAndWhatToGive).
TEST(ViewerCli, UsageErrorsNameTheWordAndWhatToGive) {
  if (!std::filesystem::exists(viewerPath())) GTEST_SKIP() << "radmesh-view is not built";
  CommandRun run = runCommand(viewerPath() + " --sizes 3");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("radmesh-view: error: --sizes is not an option of radmesh-view (did you mean --size?)"),
            std::string::npos)
      << run.output;
  run = runCommand(viewerPath() + " --resolution x");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("radmesh-view: error: --resolution: x is not a whole number"), std::string::npos)
      << run.output;
}

// A file the viewer would write over is refused before the window opens: the scene itself (a
// built-in's asset too, here through a link), or the checkpoint --resume reads; radmesh solve
// refuses a built-in's asset and the checkpoint it resumes as outputs the same way.
TEST(ViewerCli, OutputsThatWouldReplaceTheSceneOrTheCheckpointAreRefused) {
  if (!std::filesystem::exists(viewerPath())) GTEST_SKIP() << "radmesh-view is not built";
  const std::string scene = tempPath("room.gltf");
  std::filesystem::copy_file(test::dataPath("yup_room.gltf"), scene);
  const std::string before = readBytes(scene);
  CommandRun run = runCommand(viewerPath() + " " + scene + " --steps 1 --screenshot " + scene);
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--screenshot '" + scene + "': the screenshot is PNG"), std::string::npos) << run.output;
  const std::string png = tempPath("room.png");
  std::filesystem::create_symlink(scene, png);
  run = runCommand(viewerPath() + " " + scene + " --steps 1 --screenshot " + png);
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--screenshot '" + png + "' is the scene being solved"), std::string::npos) << run.output;
  EXPECT_EQ(readBytes(scene), before);

  const std::string asset = tempPath("cornell-asset.ckpt");
  std::filesystem::create_symlink(test::sourceDir() / "assets" / "cornell.gltf", asset);
  run = runCommand(viewerPath() + " cornell --checkpoint " + asset);
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--checkpoint '" + asset + "' is the scene being solved"), std::string::npos) << run.output;
  run = radmesh("solve cornell --max-iterations 1 --checkpoint " + asset);
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--checkpoint '" + asset + "' is the scene being solved"), std::string::npos) << run.output;

  const std::string checkpoint = tempPath("c.glb");
  ASSERT_EQ(radmesh("solve cornell --cell 0.1 --resolution 32 --max-iterations 2 --quiet --checkpoint " + checkpoint)
                .exitCode,
            0);
  const std::string saved = readBytes(checkpoint);
  run = radmesh("solve cornell --cell 0.1 --resolution 32 --max-iterations 3 --resume " + checkpoint + " --out " +
                checkpoint);
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--out '" + checkpoint + "' is the checkpoint --resume reads"), std::string::npos)
      << run.output;
  EXPECT_EQ(readBytes(checkpoint), saved);
  // Going on saving where it resumed from stays allowed.
  EXPECT_EQ(radmesh("solve cornell --cell 0.1 --resolution 32 --max-iterations 3 --quiet --resume " + checkpoint +
                    " --checkpoint " + checkpoint)
                .exitCode,
            0);
}

// A window size is read whole, within what X and the panel allow, and every usage error exits 2
// as radmesh's do (CLI11's own codes were 104 to 109).
TEST(ViewerCli, SizesAndUsageErrorsAreRefusedBeforeAWindowOpens) {
  if (!std::filesystem::exists(viewerPath())) GTEST_SKIP() << "radmesh-view is not built";
  for (const std::string size : {"640x480junk", "99999999999x720", "100000x100000", "64x64", "1280"}) {
    const CommandRun run = runCommand(viewerPath() + " cornell --size " + size);
    EXPECT_EQ(run.exitCode, 2) << size << ": " << run.output;
    EXPECT_NE(run.output.find("--size '" + size + "' is not WxH with a width of 444 to 16384"), std::string::npos)
        << run.output;
  }
  for (const std::string flags : {"--cell abc", "--steps 0", "--bogus"}) {
    const CommandRun run = runCommand(viewerPath() + " cornell " + flags);
    EXPECT_EQ(run.exitCode, 2) << flags << ": " << run.output;
  }
  // With no display to open a window on: --cell is refused first (the solve refused it in the window).
  const CommandRun cell = runCommand("env -u DISPLAY " + viewerPath() + " cornell --cell 0");
  EXPECT_EQ(cell.exitCode, 2) << cell.output;
  EXPECT_EQ(cell.output, "radmesh-view: error: --cell must be a finite grid size in metres greater than 0, got 0; use "
                         "e.g. --cell 0.381 (15 inches, the paper's grid)\n");
  // The viewer's 0 threads leaves a core to drawing, and says so, in --help as solve's "(0: every core)".
  const CommandRun help = runCommand(viewerPath() + " --help");
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.output.find("Host threads of the solve (0: every core but one, left to drawing"), std::string::npos)
      << help.output;
  const CommandRun threads = runCommand(viewerPath() + " cornell --threads -1");
  EXPECT_NE(threads.output.find("give 0 (every core but one, left to drawing)"), std::string::npos) << threads.output;
  const CommandRun render = radmesh("render cornell --size 640x480junk --out " + tempPath("a.png"));
  EXPECT_EQ(render.exitCode, 2) << render.output;
  EXPECT_NE(render.output.find("--size '640x480junk' is not WxH"), std::string::npos) << render.output;
}

// A flag for what the viewer's solve does not run is refused naming the flag to add, by the same
// rule as solve's (it was taken without a word).
TEST(ViewerCli, FlagsThatShapeNothingAreRefusedAsSolveDoes) {
  if (!std::filesystem::exists(viewerPath())) GTEST_SKIP() << "radmesh-view is not built";
  const std::pair<std::string, std::string> cases[] = {
      {"--backend native --mapping cut-and-stack", "--mapping shapes the emulated MP-1, and --backend is native"},
      {"--backend native --pe-grid 128x128", "--pe-grid shapes the emulated MP-1"},
      {"--backend native --projection hemicube --ratio 2", "--ratio shapes the single plane, and --projection is hemicube"},
      {"--portal-bins 8", "--portal-bins shapes a cells solve, and --cells is off: add --cells auto"},
      {"--exchange-shots 8", "--exchange-shots shapes a cells solve"},
      {"--min-element 0.1", "--min-element shapes the elements, and --subdivide is off"},
      {"--sky-model cie-overcast", "--sky-model requires --sky"},
      {"--min-frames 5 --frames 3", "--min-frames times a --steps run"},
  };
  for (const auto& [flags, message] : cases) {
    const CommandRun run = runCommand(viewerPath() + " cornell " + flags);
    EXPECT_EQ(run.exitCode, 2) << flags << ": " << run.output;
    EXPECT_NE(run.output.find(message), std::string::npos) << flags << ": " << run.output;
  }
}

// --checkpoint is checked at launch, by radmesh solve's rule: a save to it failed only when asked
// for, perhaps hours later.
TEST(ViewerCli, ACheckpointPathThatCannotBeWrittenIsRefusedAtLaunch) {
  if (!std::filesystem::exists(viewerPath())) GTEST_SKIP() << "radmesh-view is not built";
  const std::string folder = tempPath("folder");
  std::filesystem::create_directories(folder);
  const std::pair<std::string, std::string> cases[] = {
      {"/nonexistent-radmesh/x.ckpt", "--checkpoint '/nonexistent-radmesh/x.ckpt': the folder '/nonexistent-radmesh' "
                                      "does not exist: create it (mkdir -p /nonexistent-radmesh) or give another path"},
      {folder, "--checkpoint '" + folder + "' is a folder: give the path of a file in it"},
  };
  for (const auto& [path, message] : cases) {
    CommandRun run = runCommand(viewerPath() + " cornell --checkpoint " + path);
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_EQ(run.output, "radmesh-view: error: " + message + "\n");
    run = radmesh("solve cornell --checkpoint " + path);
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_EQ(run.output, "radmesh: error: " + message + "\n");
  }
}

// The viewer's defaults are no preset's: a solve's checkpoint is refused with the preset to give,
// as docs/checkpoints.md says (it listed five flags and "the options it was written with").
TEST(ViewerCli, AResumeOfASolvesCheckpointNamesItsPreset) {
  const std::string viewer = windowed();
  if (viewer.empty()) GTEST_SKIP() << "radmesh-view or xvfb-run is missing";
  const std::string checkpoint = tempPath("bake.ckpt");
  ASSERT_EQ(radmesh("solve cornell --cell 0.2 --max-iterations 2 --quiet --checkpoint " + checkpoint).exitCode, 0);
  CommandRun run = runCommand(viewer + "cornell --cell 0.2 --resume " + checkpoint + " --frames 2");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("(fix: resume with the options it was written with (--preset bake, on the native back "
                            "end), or solve from scratch without --resume)"),
            std::string::npos)
      << run.output;
  run = runCommand(viewer + "cornell --cell 0.2 --preset bake --resume " + checkpoint + " --frames 2");
  EXPECT_EQ(run.exitCode, 0) << run.output;
}

// A cells solve of an open-sided model keeps the view in from outside: the eye, in no cell, was
// sent into the Cornell box, half of the picture the void behind its open side. From outside, the
// background shows either side of the box, the red wall left, the green right.
TEST(ViewerCli, ACellsSolveOfAnOpenBoxKeepsTheViewFromOutside) {
  const std::string viewer = windowed();
  if (viewer.empty()) GTEST_SKIP() << "radmesh-view or xvfb-run is missing";
  const std::string png = tempPath("cornell-cells.png");
  const CommandRun run = runCommand(viewer + "cornell --cells auto --cell 0.1 --frames 60 --screenshot " + png);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Image picture = readPng(png);
  ASSERT_EQ(picture.width, 1280);
  auto pixel = [&](int x, int y) { return &picture.rgba[4 * (size_t(y) * picture.width + x)]; };
  for (int x : {20, 880}) EXPECT_LT(pixel(x, 360)[0] + pixel(x, 360)[1] + pixel(x, 360)[2], 30) << x;  // background
  EXPECT_GT(pixel(200, 360)[0], 2 * pixel(200, 360)[1]);  // red
  EXPECT_GT(pixel(700, 360)[1], pixel(700, 360)[0]);      // green
}

// --steps N after --resume takes N more iterations, then the screenshot: the run ends at the
// checkpoint's iteration plus N (it ended wherever the count from 0 was first passed).
TEST(ViewerCli, StepsCountFromTheResumedIteration) {
  const std::string viewer = windowed();
  if (viewer.empty()) GTEST_SKIP() << "radmesh-view or xvfb-run is missing";
  const std::string checkpoint = tempPath("c20.ckpt"), png = tempPath("c25.png");
  const std::string options = " --cell 0.1 --resolution 64";
  ASSERT_EQ(radmesh("solve cornell" + options + " --max-iterations 20 --quiet --checkpoint " + checkpoint).exitCode, 0);
  const CommandRun run =
      runCommand(viewer + "cornell --preset bake" + options + " --resume " + checkpoint + " --steps 5 --screenshot " + png);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("solver at iteration 25,"), std::string::npos) << run.output;
  EXPECT_TRUE(std::filesystem::exists(png));
}

// Under --cells auto a step is a round (every cell's shots and a portal exchange), as the panel's
// Step is: --steps counts rounds there, and its help says so (it said "run N iterations").
TEST(ViewerCli, StepsUnderCellsAreRounds) {
  if (!std::filesystem::exists(viewerPath())) GTEST_SKIP() << "radmesh-view is not built";
  const std::string help = runCommand(viewerPath() + " --help").output;
  EXPECT_NE(help.find("take N steps, as the panel's Step does (an iteration; with --cells auto a round: every "
                      "cell's shots and a portal exchange"),
            std::string::npos)
      << help;
  const std::string viewer = windowed();
  if (viewer.empty()) GTEST_SKIP() << "xvfb-run is missing";
  const std::string png = tempPath("rounds.png");
  const CommandRun run =
      runCommand(viewer + "two-rooms --cells auto --cell 0.5 --resolution 32 --steps 2 --screenshot " + png);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("cells solve at round 2, "), std::string::npos) << run.output;
}

// --max-iterations stops the viewer's solve as it stops solve's (the viewer had no cap).
TEST(ViewerCli, MaxIterationsStopsTheSolveAsSolvesDoes) {
  if (!std::filesystem::exists(viewerPath())) GTEST_SKIP() << "radmesh-view is not built";
  const CommandRun zero = runCommand("env -u DISPLAY -u WAYLAND_DISPLAY " + viewerPath() + " cornell --max-iterations 0");
  EXPECT_EQ(zero.exitCode, 2) << zero.output;
  EXPECT_NE(zero.output.find("--max-iterations 0"), std::string::npos) << zero.output;
  const std::string viewer = windowed();
  if (viewer.empty()) GTEST_SKIP() << "xvfb-run is missing";
  const std::string png = tempPath("capped.png");
  const CommandRun run = runCommand(viewer + "cornell --backend native --cell 0.2 --resolution 32 --max-iterations 3 "
                                             "--frames 30 --screenshot " + png);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("solver at iteration 3, "), std::string::npos) << run.output;
}

// A solve that fails before its mesh shows ends the frame report with the reason; it waited for
// frames with a mesh for ever.
TEST(ViewerCli, TheFrameReportEndsWhenTheSolveFails) {
  const std::string viewer = windowed();
  if (viewer.empty()) GTEST_SKIP() << "radmesh-view or xvfb-run is missing";
  const CommandRun run = runCommand(viewer + "cornell --cell 1e-5 --frames 3");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("radmesh-view: the solve failed: "), std::string::npos) << run.output;
}

// What the solve refuses on its thread (a scene or option error) exits 2, as radmesh solve does;
// it exited 1, as for a fault of radmesh's own.
TEST(ViewerCli, TheSolvesRefusalsExit2AsSolvesDo) {
  if (windowed().empty()) GTEST_SKIP() << "radmesh-view or xvfb-run is missing";
  const std::pair<std::string, std::string> cases[] = {
      {"--cell 1e-5", "the cell 1e-05 m would cut the scene into about 1.92e+10 patches"},
      {"--cells auto --backend mesh", "--cells auto runs on the native back end"},
      {"--pe-grid 2x2", "PE (row 0, col 0) needs 55440 bytes of local memory"},
      {"--subdivide uniform --min-element 1e-6", "--min-element 1e-06 m would cut the 1846 patches"},
  };
  // One virtual display for all: xvfb-run started many times in a row now and then fails to clean
  // up after itself (exit 5).
  std::string script;
  for (const auto& [flags, message] : cases)
    script += viewerPath() + " cornell " + flags + " --frames 2; echo \"[exit $?]\"; ";
  const CommandRun run = runCommand("timeout 300 " + xvfb() + "sh -c '" + script + "'");
  size_t from = 0;
  for (const auto& [flags, message] : cases) {
    const size_t end = run.output.find("[exit ", from);
    ASSERT_NE(end, std::string::npos) << flags << ": " << run.output;
    const std::string said = run.output.substr(from, end - from);
    EXPECT_EQ(run.output.substr(end, 9), "[exit 2]\n") << flags << ": " << said;
    EXPECT_NE(said.find("radmesh-view: the solve failed: " + message), std::string::npos) << flags << ": " << said;
    from = end + 9;
  }
}

// A --resume checkpoint missing, unreadable or of another solve is refused before the window opens
// (here there is no display to open one on), by radmesh solve --resume's own check and words, exit
// 2; it was found on the solver thread, in the window.
TEST(ViewerCli, AResumeCheckpointIsRefusedBeforeTheWindowOpens) {
  if (!std::filesystem::exists(viewerPath())) GTEST_SKIP() << "radmesh-view is not built";
  const std::string missing = tempPath("missing.ckpt"), truncated = tempPath("truncated.ckpt"),
                    folder = tempPath("folder.ckpt"), furnace = tempPath("furnace.ckpt"),
                    cornell = tempPath("cornell.ckpt");
  std::ofstream(truncated) << "RADMESHC";
  std::filesystem::create_directory(folder);
  ASSERT_EQ(radmesh("solve furnace --max-iterations 1 --quiet --checkpoint " + furnace).exitCode, 0);
  ASSERT_EQ(radmesh("solve cornell --cell 0.2 --max-iterations 1 --quiet --checkpoint " + cornell).exitCode, 0);
  const std::pair<std::string, std::string> cases[] = {
      {"--resume " + missing, missing + ": cannot be read: No such file or directory (fix: give --resume a "
                              "checkpoint written by --checkpoint)"},
      {"--resume " + folder, folder + ": is a folder, not a checkpoint"},
      {"--resume " + truncated, truncated + ": is truncated"},
      {"--preset bake --resume " + furnace, furnace + ": was written for another meshed scene"},
      {"--cell 0.2 --preset bake --resolution 64 --resume " + cornell,
       cornell + ": was written with other options: --resolution 256 there, 64 here"},
  };
  for (const auto& [flags, message] : cases) {
    const CommandRun run = runCommand("env -u DISPLAY -u WAYLAND_DISPLAY " + viewerPath() + " cornell " + flags);
    EXPECT_EQ(run.exitCode, 2) << flags << ": " << run.output;
    EXPECT_NE(run.output.find("radmesh-view: error: " + message), std::string::npos) << flags << ": " << run.output;
  }
}

// Walking interactively, a solve that fails on its thread is said in the terminal as well as the
// panel, once (it was in the panel alone); the window stays open until closed, here by timeout.
TEST(ViewerCli, AFailedSolveIsSaidInTheTerminal) {
  if (windowed().empty()) GTEST_SKIP() << "radmesh-view or xvfb-run is missing";
  const CommandRun run = runCommand("timeout -s INT 10 " + xvfb() + viewerPath() + " cornell --cell 1e-5");
  const std::string said = "radmesh-view: the solve failed: the cell 1e-05 m would cut the scene";
  const size_t first = run.output.find(said);
  EXPECT_NE(first, std::string::npos) << run.output;
  EXPECT_EQ(run.output.find(said, first + 1), std::string::npos) << "said more than once: " << run.output;
}

// --camera, --look and --exposure are radmesh render's, read by the same code: refused in the same
// words, before a window opens (here there is no display to open one on).
TEST(ViewerCli, CameraLookAndExposureAreRefusedAsRendersAre) {
  if (!std::filesystem::exists(viewerPath())) GTEST_SKIP() << "radmesh-view is not built";
  const std::pair<std::string, std::string> cases[] = {
      {"--camera 1,2", "--camera '1,2' is not a point: give three numbers in metres as X,Y,Z"},
      {"--look nan,0,0", "--look 'nan,0,0' is not a point"},
      {"--exposure 161", "--exposure 161 is out of range: give stops from -160 to 160, e.g. -2 (or leave it out: "
                         "automatic)"},
      {"--exposure nan", "--exposure nan is out of range"},
      {"--camera 0.2,0.2,0.2 --look 0.2,0.2,0.2",
       "--camera/--look: the camera position equals the look point; move one of them"},
  };
  for (const auto& [flags, message] : cases) {
    CommandRun run = runCommand("env -u DISPLAY -u WAYLAND_DISPLAY " + viewerPath() + " cornell " + flags);
    EXPECT_EQ(run.exitCode, 2) << flags << ": " << run.output;
    EXPECT_NE(run.output.find("radmesh-view: error: " + message), std::string::npos) << flags << ": " << run.output;
    run = radmesh("render cornell --cell 0.2 --iterations 1 " + flags + " --out " + tempPath("never.png"));
    EXPECT_EQ(run.exitCode, 2) << flags << ": " << run.output;
    EXPECT_NE(run.output.find("radmesh: error: " + message), std::string::npos) << flags << ": " << run.output;
  }
}

// Mean difference, in levels a channel, of `picture`'s left `reference.width` columns (the view
// beside the panel) from `reference`.
double viewDifference(const Image& picture, const Image& reference) {
  EXPECT_EQ(picture.height, reference.height);
  double sum = 0.0;
  for (int y = 0; y < reference.height; ++y)
    for (int x = 0; x < reference.width; ++x)
      for (int c = 0; c < 3; ++c)
        sum += std::abs(int(picture.rgba[4 * (size_t(y) * picture.width + x) + c]) -
                        int(reference.rgba[4 * (size_t(y) * reference.width + x) + c]));
  return sum / (3.0 * reference.width * reference.height);
}

// The viewer starts where radmesh render looks from, given the same flags for the same file, at
// the exposure given: a bake's coordinates are its own, y up (the office's scene is z up: this eye
// is (6.5, 5, 1.6) there). Its view beside the panel is render's picture of that size.
TEST(ViewerCli, ABakeIsWalkedFromWhereRenderLooksAtTheExposureGiven) {
  const std::string viewer = windowed();
  if (viewer.empty()) GTEST_SKIP() << "radmesh-view or xvfb-run is missing";
  const std::string bake = tempPath("office.glb"), rendered = tempPath("render.png"), shot = tempPath("shot.png"),
                    automatic = tempPath("automatic.png"), start = tempPath("start.png");
  ASSERT_EQ(radmesh("solve office --cell 1 --resolution 32 --until-unshot 0.2 --quiet --out " + bake).exitCode, 0);
  const std::string view = " --camera 6.5,1.6,-5 --look 1,0.8,-1";
  const CommandRun render = radmesh("render " + bake + view + " --exposure -1 --size 900x720 --out " + rendered);
  ASSERT_EQ(render.exitCode, 0) << render.output;
  for (const auto& [flags, png] : {std::pair{view + " --exposure -1", shot}, std::pair{view, automatic},
                                   std::pair{std::string(), start}}) {
    const CommandRun run = runCommand(viewer + bake + flags + " --steps 1 --screenshot " + png);
    ASSERT_EQ(run.exitCode, 0) << flags << ": " << run.output;
  }
  const Image reference = readPng(rendered);
  EXPECT_LT(viewDifference(readPng(shot), reference), 1.0);
  // Without --exposure, the automatic one (+1.3 EV); without the flags, the walkthrough's start.
  EXPECT_GT(viewDifference(readPng(automatic), reference), 20.0);
  EXPECT_GT(viewDifference(readPng(start), reference), 20.0);
}

// --strict refuses a scene that needed repairs, by radmesh solve's check and words, before a
// window opens; without it the file is read repaired (here, on to the missing display).
TEST(ViewerCli, StrictRefusesAFileThatNeededRepairsAsSolveDoes) {
  if (!std::filesystem::exists(viewerPath())) GTEST_SKIP() << "radmesh-view is not built";
  const std::string file = (test::sourceDir() / "tests" / "data" / "repaired" / "mgf_unknown_entity.mgf").string();
  const std::string noDisplay = "env -u DISPLAY -u WAYLAND_DISPLAY " + viewerPath() + " " + file;
  const CommandRun strict = runCommand(noDisplay + " --strict");
  EXPECT_EQ(strict.exitCode, 2) << strict.output;
  EXPECT_NE(strict.output.find("radmesh-view: error: " + file + ": refused under --strict (each warning an error), "
                               "for its 2 warnings:"),
            std::string::npos)
      << strict.output;
  EXPECT_NE(strict.output.find("(fix: correct what the warnings name, or leave --strict out to open it as warned)"),
            std::string::npos)
      << strict.output;
  const CommandRun repaired = runCommand(noDisplay);
  EXPECT_NE(repaired.output.find("radmesh-view: warning: " + file + ": line 14: unknown entity 'glow' skipped"),
            std::string::npos)
      << repaired.output;
  EXPECT_EQ(repaired.output.find("--strict"), std::string::npos) << repaired.output;
}

// --quiet leaves out the frame statistics printed on exit (the viewer prints no progress lines
// while it runs, so that is what solve's --quiet would leave out); the screenshot asked for is still said.
TEST(ViewerCli, QuietLeavesOutTheFrameStatistics) {
  const std::string viewer = windowed();
  if (viewer.empty()) GTEST_SKIP() << "radmesh-view or xvfb-run is missing";
  const std::string png = tempPath("quiet.png");
  const CommandRun loud = runCommand(viewer + "cornell --cell 0.2 --steps 1 --screenshot " + png);
  ASSERT_EQ(loud.exitCode, 0) << loud.output;
  EXPECT_NE(loud.output.find("radmesh-view: 1280x720; solver at iteration 1"), std::string::npos) << loud.output;
  EXPECT_NE(loud.output.find(" frames in "), std::string::npos) << loud.output;
  const CommandRun quiet = runCommand(viewer + "cornell --cell 0.2 --steps 1 --quiet --screenshot " + png);
  ASSERT_EQ(quiet.exitCode, 0) << quiet.output;
  EXPECT_EQ(quiet.output, "wrote " + png + "\n");
}

}  // namespace
}  // namespace radmesh
