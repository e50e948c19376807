// The `radmesh` command as a user runs it: exit codes, messages, and the JSON others depend on.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "tests/cli/cli_run.h"
#include "viewer/image.h"

namespace radmesh {
namespace {

TEST(Cli, InfoJsonGivesTheFurnaceFigures) {
  const CommandRun run = radmesh("info furnace --json");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const auto j = nlohmann::json::parse(run.output);
  EXPECT_EQ(j["polygons"], 6);
  EXPECT_EQ(j["emitters"], 6);
  EXPECT_GT(j["patches"].get<int>(), 6);
  EXPECT_FALSE(j["effects"]["occlusion"]["on"].get<bool>()) << j["effects"].dump();
  EXPECT_FALSE(j["effects"]["colour"]["on"].get<bool>());
  EXPECT_FALSE(j["effects"]["escape"]["on"].get<bool>());
  EXPECT_NEAR(j["total_area"].get<double>(), 6.0 * std::pow(j["bounds_max"][0].get<double>() - j["bounds_min"][0].get<double>(), 2), 1e-9);
}

TEST(Cli, SolveWritesStatsWithTheDocumentedKeysAndABalancedLedger) {
  const std::string stats = tempPath("stats.json");
  const CommandRun run = radmesh("solve cornell --preset paper --cell 0.1 --resolution 64 --until 0.9 --stats " + stats);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  std::ifstream in(stats);
  const auto j = nlohmann::json::parse(in);
  for (const char* key : {"patches", "iterations", "convergence", "seconds", "per_iteration", "ledger"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_GE(j["convergence"].get<double>(), 0.9);
  ASSERT_EQ(j["per_iteration"].size(), j["iterations"].get<size_t>());
  for (const char* key : {"iteration", "shooter", "shot_power", "convergence", "unshot_fraction", "seconds"})
    EXPECT_TRUE(j["per_iteration"][0].contains(key)) << key;
  // The native back end has no machine of its own: no shot figures, no mapping onto PEs, no machine
  // seconds printed.
  EXPECT_FALSE(j["per_iteration"][0].contains("emulated_seconds"));
  for (const char* key : {"mapping", "pe_grid", "pe_memory_kb"}) EXPECT_FALSE(j.contains(key)) << key;
  EXPECT_EQ(run.output.find("emulated"), std::string::npos) << run.output;
  EXPECT_EQ(j["per_iteration"].back()["unshot_fraction"], j["unshot_fraction"]);
  const auto& l = j["ledger"];
  const double accounted = l["absorbed"].get<double>() + l["unshot"].get<double>() +
                           l["not_captured"].get<double>() + l["escaped"].get<double>();
  EXPECT_NEAR(accounted, l["emitted"].get<double>(), 1e-9 * l["emitted"].get<double>());
  EXPECT_NEAR(l["emitted"].get<double>(), 1.41513, 1e-4);  // the Cornell light: area x E
  // The single plane of half-side 3 catches 91.69 % of a diffuse shot, and says so both ways.
  EXPECT_NEAR(j["captured_fraction"].get<double>(), 0.9169, 1e-4);
  EXPECT_NEAR(j["delta_form_factor_sum"].get<double>(), j["captured_fraction"].get<double>(), 1e-3);
  EXPECT_NE(run.output.find("projection catches 0.91688"), std::string::npos) << run.output;
  EXPECT_NEAR(j["unshot_fraction"].get<double>(), l["unshot"].get<double>() / l["emitted"].get<double>(), 1e-12);
}

TEST(Cli, SolveCellsAutoWritesPerCellStatsThatBalance) {
  const std::string stats = tempPath("stats.json");
  const CommandRun run = radmesh("solve two-rooms --cells auto --resolution 32 --until-unshot 0.05 --quiet --stats " + stats);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("2 cells, 1 portal,"), std::string::npos) << run.output;
  std::ifstream in(stats);
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["cells"], 2);
  EXPECT_EQ(j["portals"], 1);
  EXPECT_LE(j["unshot_fraction"].get<double>(), 0.05);
  const auto& l = j["ledger"];
  const double emitted = l["emitted"].get<double>();
  EXPECT_LE(l["imbalance"].get<double>(), 1e-9);
  double sumEmitted = 0.0, portalIn = 0.0, portalOut = 0.0;
  int iterations = 0;
  ASSERT_EQ(j["per_cell"].size(), 2u);
  for (const auto& cell : j["per_cell"]) {
    const auto& c = cell["ledger"];
    const double in = c["emitted"].get<double>() + c["portal_in"].get<double>();
    const double accounted = c["absorbed"].get<double>() + c["unshot"].get<double>() + c["not_captured"].get<double>() +
                             c["escaped"].get<double>() + c["portal_out"].get<double>();
    EXPECT_NEAR(accounted, in, 1e-9 * in) << cell.dump();
    sumEmitted += c["emitted"].get<double>(), portalIn += c["portal_in"].get<double>();
    portalOut += c["portal_out"].get<double>(), iterations += cell["iterations"].get<int>();
  }
  EXPECT_NEAR(sumEmitted, emitted, 1e-12 * emitted);
  EXPECT_GT(portalIn, 0.0);
  EXPECT_NEAR(portalIn, portalOut, 1e-9 * emitted);  // nothing waits after the last exchange
  EXPECT_EQ(j["iterations"], iterations);
}

TEST(Cli, SolveCellsWithPortalBinsBalancesAndSaysSo) {
  const std::string stats = tempPath("bins.json");
  const CommandRun run =
      radmesh("solve two-rooms --cells auto --portal-bins 4 --resolution 32 --until-unshot 0.05 --quiet --stats " + stats);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("in 48 direction bins"), std::string::npos) << run.output;
  std::ifstream in(stats);
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["portal_bins"], 4);
  EXPECT_LE(j["ledger"]["imbalance"].get<double>(), 1e-9);
  EXPECT_GT(j["per_cell"][1]["ledger"]["portal_in"].get<double>(), 0.0);
}

TEST(Cli, BenchCellsComparesTheCellsSolveWithTheWholeBuilding) {
  const auto j = runBench("cells two-rooms --cell 0.75 --resolution 16 --until-unshot 0.1").json;
  ASSERT_EQ(j["scenes"].size(), 1u);
  const auto& scene = j["scenes"][0];
  EXPECT_EQ(scene["cells"], 2);
  EXPECT_EQ(scene["portals"], 1);
  EXPECT_TRUE(scene["two_threads_identical"].get<bool>());
  ASSERT_EQ(scene["rooms"].size(), 2u);  // both rooms lit
  for (const char* key : {"whole_seconds", "cells_seconds", "focus_seconds", "largest_room_error"})
    EXPECT_TRUE(scene.contains(key)) << key;
}

// --skip-whole: no whole-building solve, so no error per room; the cells solve and the focus still timed.
TEST(Cli, BenchCellsSkipsTheWholeBuildingWhenAsked) {
  const BenchRun run =
      runBench("cells two-rooms --cell 0.75 --resolution 16 --until-unshot 0.1 --skip-whole --focus-cell 1");
  const auto scene = run.json["scenes"][0];
  for (const char* key : {"whole_seconds", "whole_iterations", "rooms", "largest_room_error"})
    EXPECT_FALSE(scene.contains(key)) << key;
  EXPECT_TRUE(scene["two_threads_identical"].get<bool>());
  EXPECT_EQ(scene["focus_cell"], 1);
  EXPECT_GT(scene["focus_iterations"].get<int>(), 0);
  EXPECT_GT(scene["focus_arrived_w"].get<double>(), 0.0);  // room B's light, all through the door
  EXPECT_EQ(run.output.find("whole building, 1 thread"), std::string::npos) << run.output;

  // --focus-only: the focus run alone, the same as in the full bench.
  const BenchRun focus =
      runBench("cells two-rooms --cell 0.75 --resolution 16 --until-unshot 0.1 --focus-only --focus-cell 1");
  const auto& only = focus.json["scenes"][0];
  EXPECT_FALSE(only.contains("cells_seconds"));
  EXPECT_EQ(only["focus_iterations"], scene["focus_iterations"]);
  EXPECT_EQ(only["focus_arrived_w"], scene["focus_arrived_w"]);
}

// The focus cell is solved to --focus-unshot even past the building's --until-unshot (which used to
// end the run first, the same iterations for any target, labelled as reached), and a solve that
// --max-iterations stops short is marked "+", its ratio a slowdown where it is one.
TEST(Cli, BenchCellsSolvesTheFocusToItsTargetAndMarksWhatStoppedShort) {
  const std::string bench = "cells two-rooms --cell 0.75 --resolution 16 --until-unshot 0.1 --focus-only --focus-unshot ";
  const auto loose = runBench(bench + "0.05").json["scenes"][0], tight = runBench(bench + "0.001").json["scenes"][0];
  EXPECT_TRUE(loose["focus_reached"].get<bool>());
  EXPECT_TRUE(tight["focus_reached"].get<bool>());
  EXPECT_GT(tight["focus_iterations"].get<int>(), loose["focus_iterations"].get<int>());

  const BenchRun capped = runBench("cells two-rooms --cell 0.75 --resolution 16 --until-unshot 0.1 --max-iterations 10");
  const auto& scene = capped.json["scenes"][0];
  EXPECT_FALSE(scene["whole_reached"].get<bool>());
  EXPECT_FALSE(scene["cells_reached"].get<bool>());
  EXPECT_FALSE(scene["focus_reached"].get<bool>());
  EXPECT_NE(capped.output.find(" 10+ "), std::string::npos) << capped.output;
  EXPECT_NE(capped.output.find("stopped short of 5% of its arriving light unshot"), std::string::npos) << capped.output;
  EXPECT_NE(capped.output.find("warning: --max-iterations stopped a solve short of 10% unshot"), std::string::npos)
      << capped.output;
}

// --threads sets the threads of the second cells solve, by solve's rule (0: every core); it ran on
// two whatever the machine.
TEST(Cli, BenchCellsRunsItsSecondCellsSolveOnTheThreadsGiven) {
  const std::string bench = "cells two-rooms --cell 0.75 --resolution 16 --until-unshot 0.1 --skip-whole --threads ";
  const int hardware = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  for (const int threads : {0, 1, 2}) {
    const int runs = threads == 0 ? hardware : std::min(threads, hardware);
    const BenchRun run = runBench(bench + std::to_string(threads));
    EXPECT_EQ(run.json["threads"], runs) << threads;
    const std::string row = runs == 1 ? "cells, 1 thread " : "cells, " + std::to_string(runs) + " threads ";
    const size_t first = run.output.find("cells, 1 thread ");
    ASSERT_NE(first, std::string::npos) << run.output;
    EXPECT_NE(run.output.find(row, first + 1), std::string::npos) << threads << ": " << run.output;
    EXPECT_TRUE(run.json["scenes"][0]["two_threads_identical"].get<bool>()) << threads;
  }
}

// --subdivide and --min-element reach both solves: the cells cut their patches into the elements
// `radmesh info` counts for the building; an unknown mode is refused naming the fix.
TEST(Cli, BenchCellsSolvesWithElementsWhenAsked) {
  const BenchRun run = runBench("cells two-rooms --cell 0.75 --resolution 16 --until-unshot 0.1 --skip-whole "
                                "--subdivide uniform --min-element 0.375");
  const auto& j = run.json;
  EXPECT_EQ(j["subdivide"], "uniform");
  EXPECT_EQ(j["min_element"], 0.375);
  const CommandRun info = radmesh("info two-rooms --cell 0.75 --min-element 0.375");
  ASSERT_EQ(info.exitCode, 0) << info.output;
  EXPECT_NE(info.output.find("elements        1460 with --subdivide uniform"), std::string::npos) << info.output;
  EXPECT_EQ(info.output.find("more than this machine's limit"), std::string::npos) << info.output;
  // A count no solve takes (over 20 M on any machine) is flagged where it is counted.
  const CommandRun over = radmesh("info cornell --min-element 0.0003");
  EXPECT_NE(over.output.find("elements        24587020 with --subdivide uniform --min-element 0.0003, more than "
                             "this machine's limit of "),
            std::string::npos)
      << over.output;
  EXPECT_EQ(j["scenes"][0]["cells_elements"], 1460);
  EXPECT_NE(run.output.find("uniform elements, --min-element 0.375"), std::string::npos) << run.output;

  const CommandRun bad = radmesh("bench cells two-rooms --cell 0.75 --subdivide sometimes");
  EXPECT_NE(bad.exitCode, 0);
  EXPECT_NE(bad.output.find("--subdivide"), std::string::npos) << bad.output;
}

// bench solve --cells auto times the cells solve to the unshot fraction: reached, the same
// iterations as `solve --cells auto` with the same settings.
TEST(Cli, BenchSolveTimesTheCellsSolve) {
  const auto j = runBench("solve two-rooms --cells auto --exchange-shots 8 --until 1 --until-unshot 0.1 "
                          "--projections hemicube --resolutions 16 --threads 1").json;
  EXPECT_EQ(j["cells"], "auto");
  ASSERT_EQ(j["rows"].size(), 1u);
  const auto& row = j["rows"][0];
  EXPECT_TRUE(row["reached_until"].get<bool>());
  EXPECT_LE(row["unshot_fraction"].get<double>(), 0.1);
  const std::string stats = tempPath("stats.json");
  ASSERT_EQ(radmesh("solve two-rooms --cells auto --exchange-shots 8 --until-unshot 0.1 "
                    "--projection hemicube --resolution 16 --threads 1 --quiet --stats " + stats).exitCode, 0);
  EXPECT_EQ(row["iterations_to_until"], nlohmann::json::parse(std::ifstream(stats))["iterations"]);

  CommandRun bad = radmesh("bench solve two-rooms --cells some");
  EXPECT_NE(bad.exitCode, 0);
  EXPECT_NE(bad.output.find("--cells 'some' is unknown"), std::string::npos) << bad.output;
  bad = radmesh("bench solve two-rooms --cells auto --resolutions 16");  // stops on C by default
  EXPECT_NE(bad.exitCode, 0);
  EXPECT_NE(bad.output.find("--until-unshot"), std::string::npos) << bad.output;
}

// A round is not cut short, so a cells solve may run past --max-iterations: the summary says so
// (166 149 iterations for 2000 came without a word).
TEST(Cli, ACellsSolvePastItsIterationCapSaysWhy) {
  const CommandRun run = radmesh("solve two-rooms --cells auto --cell 0.75 --resolution 16 --max-iterations 10 --quiet");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("rounds (past --max-iterations 10, which is checked between rounds)"), std::string::npos)
      << run.output;
}

TEST(Cli, CellsOptionsAreRefusedNamingTheFlag) {
  CommandRun run = radmesh("solve two-rooms --cells some");
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.output.find("--cells 'some' is unknown"), std::string::npos) << run.output;
  run = radmesh("solve two-rooms --cells auto --backend mesh");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("a machine per cell"), std::string::npos) << run.output;
  run = radmesh("solve two-rooms --cells auto --preset paper");
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.output.find("--until-unshot"), std::string::npos) << run.output;
  run = radmesh("solve two-rooms --cells auto --portal-bins 17");
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.output.find("--portal-bins 17 is out of range"), std::string::npos) << run.output;
}

// bench cells and bench solve check every value before their first solve, not after minutes of rows.
TEST(Cli, BenchesRefuseEveryImpossibleValueBeforeSolving) {
  const std::map<std::string, std::string> cases = {
      {"bench cells two-rooms --focus-cell 99", "--focus-cell 99 is not a cell of two-rooms: give 0 to 1"},
      {"bench cells two-rooms --focus-unshot nan", "--focus-unshot must be a fraction in [0, 1), e.g. 0.05; got nan"},
      {"bench cells two-rooms --portal-bins 99", "--portal-bins 99 is out of range"},
      {"bench cells two-rooms --min-element 0.1", "--min-element shapes the elements, and --subdivide is off"},
      {"bench cells two-rooms --threads -1", "-1 is not a thread count: give 0 (every core) or a positive count"},
      {"bench cells two-rooms --focus-only --threads 2",
       "bench cells --threads sets the second cells solve's threads, and --focus-only runs the focus cell alone"},
      {"bench solve furnace --scaling-cell-sizes 0", "--scaling-cell-sizes 0: give cell sizes in metres greater than 0"},
      {"bench solve furnace --scaling-cells 0", "--scaling-cell-sizes 0: give cell sizes in metres greater than 0"},
      {"bench solve furnace --scaling-cells 0.5 --scaling-resolution 0", "--scaling-resolution 0 is out of range"},
      // bench accuracy names its own lists (it named --cell, --subdivide-cells and an analytic it refuses)
      // and refuses what --quick would replace without a word.
      // Its list of grid cell sizes is --cell-sizes (--cells, an alias, is auto|off on the solving commands).
      {"bench accuracy furnace --cells 1,0", "bench accuracy --cell-sizes 0: give cell sizes in metres greater than 0"},
      {"bench accuracy furnace --cell-sizes nan", "bench accuracy --cell-sizes nan: give cell sizes in metres greater than 0"},
      {"bench accuracy furnace --projections foo", "--projections 'foo': give plane (ratios 3 and 5) or hemicube"},
      {"bench accuracy furnace --quick --resolutions 48", "--quick sets --resolutions itself"},
      {"bench accuracy furnace --quick --reference-until-unshot 0.001", "--quick sets --reference-until-unshot itself"},
      {"bench accuracy furnace --quick --reference-unshot 0.001", "--quick sets --reference-until-unshot itself"},
      {"bench accuracy furnace --quick --cells 1,0.5,0.25", "--quick sweeps at most two --cell-sizes"},
      {"bench accuracy furnace --quick --cell-sizes 1,0.5,0.25", "--quick sweeps at most two --cell-sizes"},
      // Flags for what the run does not time were dropped without a word; the cells' own refusal comes first.
      {"bench solve furnace --pe-grid 32x32", "bench solve --pe-grid shapes the emulated machine: add --backend mesh"},
      {"bench solve furnace --scaling-resolution 17", "--scaling-resolution is the resolution of the --scaling-cell-sizes sweep"},
      {"bench solve two-rooms --cells auto --backend mesh --projections hemicube --until 1 --until-unshot 0.1",
       "--cells auto runs on the native back end only"},
  };
  for (const auto& [arguments, message] : cases) {
    const CommandRun run = radmesh(arguments);
    EXPECT_EQ(run.exitCode, 2) << arguments << ": " << run.output;
    EXPECT_NE(run.output.find(message), std::string::npos) << arguments << ": " << run.output;
    for (const char* solved : {"whole building, 1 thread", "\nplane ", "\nhemicube "})
      EXPECT_EQ(run.output.find(solved), std::string::npos) << arguments << ": solved before refusing";
  }
}

// A flag that shapes what the solve does not run would be dropped without a word: refused, naming
// the flag to add. Beside what it shapes, it is taken.
TEST(Cli, FlagsForWhatTheSolveDoesNotRunAreRefused) {
  const std::map<std::string, std::string> cases = {
      {"--ratio 5", "--ratio shapes the single plane, and --projection is hemicube: add --projection plane"},
      {"--mapping adaptive", "--mapping shapes the emulated MP-1, and --backend is native: add --backend mesh"},
      {"--pe-grid 32x32", "--pe-grid shapes the emulated MP-1, and --backend is native: add --backend mesh"},
      {"--exchange-shots 4", "--exchange-shots shapes a cells solve, and --cells is off: add --cells auto"},
      {"--portal-bins 2", "--portal-bins shapes a cells solve, and --cells is off: add --cells auto"},
  };
  for (const auto& [flags, message] : cases) {
    const CommandRun run = radmesh("solve furnace --max-iterations 1 " + flags);
    EXPECT_EQ(run.exitCode, 2) << flags << ": " << run.output;
    EXPECT_NE(run.output.find(message), std::string::npos) << flags << ": " << run.output;
  }
  for (const std::string flags : {"--projection plane --ratio 5", "--backend mesh --mapping adaptive --ratio 5",
                                  "--preset paper --ratio 5"}) {
    const CommandRun run = radmesh("solve furnace --max-iterations 1 --quiet " + flags);
    EXPECT_EQ(run.exitCode, 0) << flags << ": " << run.output;
  }
}

// radmesh-view takes --portal-bins, --preset and --pe-grid as solve does, and refuses a count out
// of range, an unknown preset or a machine that is not one the same way, before any window opens.
TEST(Cli, ViewerRefusesPortalBinsAsSolveDoes) {
  const std::string viewer = (test::binaryDir() / "viewer" / "radmesh-view").string();
  if (!std::filesystem::exists(viewer)) GTEST_SKIP() << "radmesh-view is not built";
  const CommandRun run = runCommand(viewer + " two-rooms --cells auto --portal-bins 17");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--portal-bins 17 is out of range"), std::string::npos) << run.output;
  // Checks made while parsing exit 2 with the message too (they used to abort the viewer).
  for (const auto& [flags, message] : {std::pair{"--preset fast", "--preset 'fast' is unknown: give bake"},
                                       {"--pe-grid 3", "--pe-grid '3' is not COLSxROWS"}}) {
    const CommandRun refused = runCommand(viewer + " two-rooms " + flags);
    EXPECT_EQ(refused.exitCode, 2) << flags;
    EXPECT_NE(refused.output.find(std::string("radmesh-view: error: ") + message), std::string::npos) << refused.output;
  }
}

// CLI11's own refusals (a value not in a list, an unknown flag, a number that is not one) exit 2
// like radmesh's; help still exits 0.
TEST(Cli, EveryUsageErrorExits2) {
  CommandRun run = radmesh("info furnace --cell-groups bogus");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--cell-groups"), std::string::npos) << run.output;
  run = radmesh("solve furnace --bogus");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--bogus"), std::string::npos) << run.output;
  run = radmesh("solve furnace --resolution abc");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--resolution"), std::string::npos) << run.output;
  EXPECT_EQ(radmesh("--help").exitCode, 0);
  EXPECT_EQ(radmesh("solve --help").exitCode, 0);
  // An empty value is no number: CLI11 would read it as 0 (the cache off, the stopping rule changed).
  for (const std::string arguments : {"solve furnace --cache-mb ''", "solve furnace --until-unshot=", "info '' "}) {
    run = radmesh(arguments);
    EXPECT_EQ(run.exitCode, 2) << arguments << ": " << run.output;
    EXPECT_NE(run.output.find("is given an empty value: give it a value, or leave it out"), std::string::npos)
        << arguments << ": " << run.output;
  }
}

// CLI11's own refusals ("Could not convert: --resolution = x", "A subcommand is required") in words
// that name what was wrong and what to give.
TEST(Cli, UsageErrorsNameTheWordAndWhatToGive) {
  const std::pair<std::string, std::string> cases[] = {
      {"", "radmesh: error: radmesh needs a command: give one of info, solve, render, bench, plot"},
      {"slove furnace", "radmesh: error: 'slove' is not a command of radmesh: give one of info, solve"},
      {"bench", "radmesh: error: radmesh bench needs a command: give one of solve, accuracy, cells"},
      {"solve furnace --resolution x", "radmesh: error: --resolution: x is not a whole number: give a whole number"},
      {"solve furnace --until-unshot x", "radmesh: error: --until-unshot: x is not a number: give a number"},
      {"bench solve furnace --resolutions 1.5,2",
       "--resolutions: 1.5,2 is not a list of whole numbers: give whole numbers separated by commas"},
      {"solve furnace --resolution", "radmesh: error: --resolution is given no value: give it a whole number"},
      {"solve furnace --thread 2", "--thread is not an option of radmesh solve (did you mean --threads?)"},
      {"solve furnace --projection hemicube --projections plane",
       "--projections is not an option of radmesh solve (did you mean --projection?)"},
      {"solve furnace --zzzzzzzz", "--zzzzzzzz is not an option of radmesh solve: radmesh solve --help lists them"},
      {"solve furnace cornell", "'cornell' is one argument too many for radmesh solve"},
      {"solve furnace --sky 1000 --sky 2000",
       "radmesh: error: --sky is given 2 times: give it once (radmesh solve --help)"},
  };
  for (const auto& [arguments, message] : cases) {
    const CommandRun run = radmesh(arguments);
    EXPECT_EQ(run.exitCode, 2) << arguments << ": " << run.output;
    EXPECT_NE(run.output.find(message), std::string::npos) << arguments << ": " << run.output;
  }
}

// An option left without its value before the next option is named with what it takes: CLI11
// took the next option as the value, and then refused what followed as one argument too many.
TEST(Cli, AnOptionWithoutItsValueBeforeAnotherIsNamedWithItsValues) {
  const std::pair<std::string, std::string> cases[] = {
      {"solve two-rooms --cells --threads 1",
       "radmesh: error: --cells is given no value (--threads, after it, is an option): give it auto or off, or "
       "leave it out\n"},
      {"solve two-rooms --cells --quiet", "--cells is given no value (--quiet, after it, is an option): give it auto or off"},
      {"render cornell --projection --quiet --out x.png", "--projection is given no value (--quiet, after it, is an "
                                                          "option): give it plane, hemicube or analytic"},
      {"solve cornell --resolution --threads 1", "--resolution is given no value (--threads, after it, is an option): "
                                                 "give it a whole number"},
      {"bench solve cornell --backend --cells auto", "--backend is given no value (--cells, after it, is an option): "
                                                     "give it native or mesh"},
      {"solve two-rooms --threads 1 --cells", "--cells is given no value: give it auto or off, or leave it out"},
  };
  for (const auto& [arguments, message] : cases) {
    const CommandRun run = radmesh(arguments);
    EXPECT_EQ(run.exitCode, 2) << arguments << ": " << run.output;
    EXPECT_NE(run.output.find(message), std::string::npos) << arguments << ": " << run.output;
  }
  EXPECT_NE(radmesh("solve --help").output.find("--cells auto|off=off"), std::string::npos);
}

TEST(Cli, ImpossibleOptionsAreRefusedNamingTheFlag) {
  CommandRun run = radmesh("solve furnace --resolution 8");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--resolution"), std::string::npos) << run.output;
  run = radmesh("info furnace --cell 0");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--cell"), std::string::npos) << run.output;
  // Refused before it is announced as the cell.
  run = radmesh("solve furnace --cell -1");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--cell must be a finite grid size in metres greater than 0, got -1"), std::string::npos)
      << run.output;
  EXPECT_EQ(run.output.find("as --cell gives"), std::string::npos) << run.output;
  run = radmesh("solve furnace --projection sphere");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("sphere"), std::string::npos) << run.output;
  // A count or time that must be positive says so, not CLI11's range up to the largest double.
  for (const std::string command : {"solve two-rooms --cells auto --exchange-shots 0",
                                    "solve furnace --checkpoint out.ckpt --checkpoint-every -1"}) {
    run = radmesh(command);
    EXPECT_EQ(run.exitCode, 2) << command;
    EXPECT_NE(run.output.find("is not above 0: give a number above 0"), std::string::npos) << run.output;
    EXPECT_LT(run.output.size(), 200u) << run.output;
  }
  run = radmesh("solve two-rooms --cells auto --exchange-shots abc");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("abc is not a number: give a number above 0"), std::string::npos) << run.output;
  run = radmesh("solve furnace --threads -1");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--threads: -1 is not a thread count: give 0 (every core) or a positive count"),
            std::string::npos)
      << run.output;
  // A cell too small to lay a grid at is refused as the cell, not blamed on a polygon.
  run = radmesh("info two-rooms --cell 1e-308");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("the cell 1e-308 m would cut the scene into uncountably many patches"), std::string::npos)
      << run.output;
  // info counts the elements --min-element would make: a length it cannot be is refused there too.
  for (const std::string value : {"nan", "-1", "inf"}) {
    run = radmesh("info furnace --min-element " + value);
    EXPECT_EQ(run.exitCode, 2) << value << ": " << run.output;
    EXPECT_NE(run.output.find("--min-element " + value + " is out of range"), std::string::npos) << run.output;
  }
}

// More threads than the machine runs at once only wait, each with its own scratch: cut to that many.
TEST(Cli, ThreadsBeyondTheMachinesAreCutToItsCount) {
  const unsigned hardware = std::thread::hardware_concurrency();
  if (hardware == 0) GTEST_SKIP() << "this machine does not say how many threads it runs";
  for (const std::string command : {"solve furnace --cell 0.25 --max-iterations 2 --threads 100000",
                                    "bench solve furnace --cell 0.25 --resolutions 16 --until 0.5 --threads 100000"}) {
    const CommandRun run = radmesh(command);
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find(fmt::format("radmesh: warning: --threads 100000 is more than the {} this machine runs "
                                          "at once: using {}", hardware, hardware)),
              std::string::npos)
        << run.output;
  }
  // The viewer warns under its own name (refused right after, before a window opens).
  const std::string viewer = (test::binaryDir() / "viewer" / "radmesh-view").string();
  if (!std::filesystem::exists(viewer)) return;
  const CommandRun run = runCommand(viewer + " two-rooms --cells auto --threads 100000 --portal-bins 17");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("radmesh-view: warning: --threads 100000"), std::string::npos) << run.output;
}

// Analytic form factors have no N x N: the solve line names the projection alone.
TEST(Cli, AnAnalyticSolveSaysNoResolution) {
  const CommandRun run = radmesh("solve furnace --projection analytic --max-iterations 2");
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("patches, analytic, k=1,"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("analytic 256x256"), std::string::npos) << run.output;
}

// Analytic form factors see through everything: asked for where patches can hide one another, they
// are refused before the solve (a desk's shadow was lit without a word), by solve, render and the viewer.
TEST(Cli, AnalyticFormFactorsAreRefusedWherePatchesHideOneAnother) {
  const std::string viewer = (test::binaryDir() / "viewer" / "radmesh-view").string();
  std::vector<std::string> commands = {"solve office --cell 1 --projection analytic",
                                       "render office --cell 1 --projection analytic --out " + tempPath("a.png")};
  for (const std::string& command : commands) {
    const CommandRun run = radmesh(command);
    EXPECT_EQ(run.exitCode, 2) << command << ": " << run.output;
    EXPECT_NE(run.output.find("--projection analytic has no visibility, and office is not a convex enclosure"),
              std::string::npos)
        << command << ": " << run.output;
    EXPECT_EQ(run.output.find("iteration"), std::string::npos) << command << ": refused before the solve";
  }
  if (!std::filesystem::exists(viewer)) return;
  const CommandRun run = runCommand(viewer + " office --backend native --projection analytic");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("radmesh-view: error: --projection analytic has no visibility"), std::string::npos)
      << run.output;
}

TEST(Cli, EveryBadFileIsRefusedWithItsNameAndNoCrash) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::dataPath("bad"))) {
    const std::string path = entry.path().string();
    if (path.find("_b.mgf") != std::string::npos) continue;  // the partner of an include cycle
    const CommandRun run = radmesh("info " + path);
    EXPECT_EQ(run.exitCode, 2) << path << "\n" << run.output;
    EXPECT_NE(run.output.find(entry.path().filename().string()), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("fix:"), std::string::npos) << run.output;
    ++files;
  }
  EXPECT_GE(files, 20);
}

TEST(Cli, MissingFileAndUnknownSceneNameSayWhatIsAccepted) {
  CommandRun run = radmesh("info does-not-exist.gltf");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("does-not-exist.gltf"), std::string::npos) << run.output;
  run = radmesh("info nowhere");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("office"), std::string::npos) << run.output;
}

// A CSV file as rows of fields, the header first.
std::vector<std::vector<std::string>> readCsv(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    rows.emplace_back();
    std::stringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) rows.back().push_back(field);
  }
  return rows;
}

// The default cells were a room's (0.5, 0.381, 0.25 m) whatever the scene: the 0.55 m Cornell box
// was 40 patches at each, its own reference. They follow the cell its solve chooses, 0.0343 m.
TEST(Cli, BenchAccuracysDefaultCellsFollowTheScenesSize) {
  const std::string json = tempPath("cornell-cells.json");
  const CommandRun run = radmesh("bench accuracy cornell --projections hemicube --resolutions 16 "
                                 "--reference-resolution 16 --reference-until 0.5 --reference-unshot 0.5 --threads 2 --json " + json);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  std::ifstream in(json);
  const auto j = nlohmann::json::parse(in);
  std::set<double> cells;
  for (const auto& point : j["points"]) cells.insert(point["cell"].get<double>());
  ASSERT_EQ(cells.size(), 3u);
  const double chosen = 0.549 / 16;  // a sixteenth of the box's smallest extent, to 3 figures
  const double expected[] = {chosen * 0.25 / 0.381, chosen, chosen * 0.5 / 0.381};
  int k = 0;
  for (double cell : cells) EXPECT_NEAR(cell, expected[k++], 2e-3 * chosen);
}

// bench solve's patch-count sweep is a list of cell sizes, named as bench accuracy's --cell-sizes;
// its first name, --scaling-cells, sets the same.
TEST(Cli, BenchSolvesScalingCellSizesTakesItsFormerName) {
  const std::string bench = "solve furnace --projections plane --resolutions 16 --max-iterations 2 "
                            "--scaling-resolution 16 ";
  for (const std::string name : {"--scaling-cell-sizes", "--scaling-cells"}) {
    const nlohmann::json scaling = runBench(bench + name + " 0.5,0.25").json["scaling"];
    ASSERT_EQ(scaling.size(), 2u) << name << ": " << scaling.dump();
    EXPECT_EQ(scaling[0]["cell"], 0.5) << name;
    EXPECT_EQ(scaling[0]["patches"], 24) << name;
    EXPECT_EQ(scaling[1]["cell"], 0.25) << name;
    EXPECT_EQ(scaling[1]["patches"], 96) << name;
  }
}

// The reference's unshot stop is named as --until-unshot, beside --reference-until; its first
// name, --reference-unshot, sets the same.
TEST(Cli, BenchAccuracysReferenceUntilUnshotTakesItsFormerName) {
  const auto referenceOf = [](const std::string& stop) {
    const std::string json = tempPath("reference.json");
    const CommandRun run = radmesh("bench accuracy furnace --projections hemicube --resolutions 16 --cell-sizes 0.5 "
                                   "--reference-resolution 16 --reference-until 0.5 --json " + json + " " + stop);
    EXPECT_EQ(run.exitCode, 0) << stop << ": " << run.output;
    return nlohmann::json::parse(std::ifstream(json))["references"][0]["how"].get<std::string>();
  };
  const std::string reached = referenceOf("--reference-until-unshot 0.05");
  EXPECT_NE(reached.find(" % unshot"), std::string::npos) << reached;
  EXPECT_EQ(referenceOf("--reference-unshot 0.05"), reached);
  EXPECT_NE(referenceOf("--reference-until-unshot 0.5"), reached);  // a stop it reaches sooner
  for (const std::string name : {"--reference-until-unshot", "--reference-unshot"}) {
    const CommandRun run = radmesh("bench accuracy furnace " + name + " 1.5");
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_EQ(run.output, "radmesh: error: --reference-until-unshot must be a fraction in (0, 1), e.g. 0.001\n");
  }
}

// A reference cut short by the cap is refused, and the refusal names the options that lift it.
TEST(Cli, BenchAccuracysReferenceCutShortNamesItsCap) {
  const std::string common = "bench accuracy furnace --projections hemicube --resolutions 16 --cell-sizes 0.5 "
                             "--reference-resolution 16 --reference-until 0.5 --reference-until-unshot 0.05 ";
  const CommandRun capped = radmesh(common + "--max-iterations 1");
  EXPECT_NE(capped.exitCode, 0);
  EXPECT_NE(capped.output.find("after 10 iterations"), std::string::npos) << capped.output;
  EXPECT_NE(capped.output.find("(raise --max-iterations or --reference-until-unshot)"), std::string::npos) << capped.output;
  EXPECT_EQ(radmesh(common + "--max-iterations 100").exitCode, 0);
}

// The room's cells, given: at 128x128 the pixels resolve their patches (the furnace's own cell,
// 0.0625 m, is finer than a pixel there and moves the plane's error by 2 %).
TEST(Cli, BenchAccuracyQuickWritesTableCsvAndJson) {
  const std::string dir = tempPath("accuracy");
  const std::string json = tempPath("furnace.json");
  std::filesystem::remove_all(dir);
  const CommandRun run = radmesh("bench accuracy furnace --quick --cells 0.5,0.381 --out-dir " + dir + " --json " + json);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/furnace.json"));  // the raw JSON goes where --json says only
  std::ifstream in(json);
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(readCsv(dir + "/furnace.csv").size(), 1u + 18u);
  // The traces' CSV keeps, of each trace, the first iteration at C >= 0.95 and the last.
  const auto traces = readCsv(dir + "/furnace-traces.csv");
  ASSERT_EQ(traces.front().size(), 9u);
  ASSERT_EQ(j["traces"].size(), 2u);
  std::vector<std::string> iterations;
  for (size_t row = 1; row < traces.size(); ++row) iterations.push_back(traces[row][0] + " " + traces[row][4]);
  for (const auto& trace : j["traces"]) {
    const auto& points = trace["points"];
    const std::string projection = trace["label"].get<std::string>().substr(0, trace["label"].get<std::string>().find(' '));
    size_t first95 = 0;
    while (first95 + 1 < points.size() && points[first95]["convergence"].get<double>() < 0.95) ++first95;
    for (const auto& point : {points[first95], points.back()}) {
      const std::string key = projection + " " + std::to_string(point["iteration"].get<int>());
      EXPECT_NE(std::find(iterations.begin(), iterations.end(), key), iterations.end()) << key;
    }
  }
  for (const std::string plot : {"error-vs-time", "image-error-vs-time", "error-vs-convergence"})
    EXPECT_EQ(std::filesystem::exists(dir + "/furnace-" + plot + ".png"), gnuplotInstalled()) << plot;
  EXPECT_EQ(j["points"].size(), 18u);  // 3 settings x 3 resolutions x 2 cells
  ASSERT_EQ(j["references"].size(), 2u);
  EXPECT_NE(j["references"][0]["how"].get<std::string>().find("analytic"), std::string::npos);
  // Pictures compare across meshes: the finest reference is the pictures' reference itself, and
  // the furnace's uniform answer looks the same on the coarser mesh, but for the last 0.5 % of
  // convergence that the ambient term only approximates.
  EXPECT_EQ(j["references"][0]["image_rmse"].get<double>(), 0.0);
  EXPECT_LT(j["references"][1]["image_rmse"].get<double>(), 2.0);
  // The furnace's answer is B = E/(1-rho) everywhere, so B - E = E rho/(1-rho). The hemicube
  // catches the whole hemisphere; a single plane catching c of each shot converges to
  // B - E = E rho c/(1 - rho c): with rho = 0.5, 15.3 % low at ratio 3 (c = 0.9169) and 6.1 % at
  // ratio 5 (c = 0.9683, the square plane's closed form). At 128x128 the pixels resolve the
  // patches, and that is what shows.
  auto expectedError = [](double c) { return 1.0 - (0.5 * c / (1.0 - 0.5 * c)) / (0.5 / 0.5); };
  std::map<std::string, double> worstPicture;
  int checked = 0;
  for (const auto& p : j["points"]) {
    const std::string key = p["projection"].get<std::string>() + std::to_string(p["ratio"].get<double>());
    worstPicture[key] = std::max(worstPicture[key], p["image_rmse_at_99"].get<double>());
    if (p["resolution"] != 128) continue;
    const double error = p["error_at_99"].get<double>();
    if (key == "plane3.000000") {
      EXPECT_NEAR(error, expectedError(0.9169), 0.01) << p.dump();
    } else if (key == "plane5.000000") {
      EXPECT_NEAR(error, expectedError(0.9683), 0.01) << p.dump();
    } else {
      EXPECT_LT(error, 0.01) << p.dump();
    }
    ++checked;
  }
  EXPECT_EQ(checked, 6);
  // The plane's lost 8.3 % darkens the picture by levels; the hemicube's does not.
  EXPECT_LT(worstPicture["hemicube3.000000"], 2.0);
  EXPECT_GT(worstPicture["plane3.000000"], 3.0);
}

// --reference-cell: the pictures' reference is a finer patch mesh, solved but not swept, so the
// finest swept mesh is scored too; each swept mesh keeps its own reference for the same-mesh error.
TEST(Cli, BenchAccuracyScoresTheFinestSweptMeshAgainstAFinerReferenceCell) {
  const std::string sweep =
      "bench accuracy cornell --cells 0.2,0.1 --resolutions 32 --projections hemicube --reference-resolution 64 "
      "--threads 1";
  const std::string own = tempPath("cornell-own.json"), finer = tempPath("cornell-finer.json");
  const std::string dir = tempPath("accuracy-reference-cell");
  std::filesystem::remove_all(dir);
  CommandRun run = radmesh(sweep + " --json " + own);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  run = radmesh(sweep + " --reference-cell 0.05 --out-dir " + dir + " --json " + finer);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("cell 0.05 m, 964 patches, not swept: the pictures' reference hemicube 64x64"),
            std::string::npos)
      << run.output;
  std::ifstream ownIn(own), finerIn(finer);
  const auto a = nlohmann::json::parse(ownIn), b = nlohmann::json::parse(finerIn);
  // Without it the finest swept mesh is its own pictures' reference and scores nothing.
  EXPECT_EQ(a["picture_reference"]["cell"].get<double>(), 0.1);
  EXPECT_EQ(a["references"][0]["image_rmse"].get<double>(), 0.0);
  EXPECT_EQ(b["picture_reference"]["cell"].get<double>(), 0.05);
  EXPECT_EQ(b["picture_reference"]["patches"].get<int>(), 964);
  ASSERT_EQ(b["references"].size(), 2u);  // the swept meshes only
  EXPECT_EQ(b["references"][0]["cell"].get<double>(), 0.1);
  // The 0.1 m mesh's converged pictures are 5.4 levels from the 0.05 m mesh's, the 0.2 m mesh's 12.7.
  EXPECT_GT(b["references"][0]["image_rmse"].get<double>(), 2.0);
  EXPECT_GT(b["references"][1]["image_rmse"].get<double>(), b["references"][0]["image_rmse"].get<double>());
  ASSERT_EQ(b["points"].size(), 2u);
  const auto& finest = b["points"][1];
  ASSERT_EQ(finest["cell"].get<double>(), 0.1);
  EXPECT_GT(finest["image_rmse_at_99"].get<double>(), 2.0);
  EXPECT_NE(finest["image_rmse_at_99"].get<double>(), a["points"][1]["image_rmse_at_99"].get<double>());
  // The same-mesh error is the same: its reference is still each swept mesh's own.
  for (size_t i = 0; i < 2; ++i)
    EXPECT_EQ(b["points"][i]["error_at_99"].get<double>(), a["points"][i]["error_at_99"].get<double>()) << i;
  // The CSV names the cell every row was scored against.
  const auto rows = readCsv(dir + "/cornell.csv");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].back(), "reference_cell_m");
  EXPECT_EQ(rows[1].back(), "0.05");
  EXPECT_EQ(rows[2].back(), "0.05");
}

TEST(Cli, BenchAccuracyRefusesAnImpossibleReference) {
  for (const std::string value : {"1", "0.5", "-0.1", "nan"}) {
    const CommandRun run = radmesh("bench accuracy furnace --cell-sizes 1,0.5 --reference-cell=" + value);
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("--reference-cell " + value +
                              ": give a cell finer than the finest of --cell-sizes (0.5 m), e.g. 0.25, or 0 for the "
                              "finest of --cell-sizes itself"),
              std::string::npos)
        << run.output;
    EXPECT_EQ(run.output.find("reference analytic"), std::string::npos) << "refused before any solve";
  }
  // A hemicube reference coarser than the sweep it judges (cornell is not convex: its reference projects).
  const CommandRun coarse = radmesh("bench accuracy cornell --cells 0.2 --resolutions 32 --projections hemicube "
                                    "--reference-resolution 16");
  EXPECT_EQ(coarse.exitCode, 2) << coarse.output;
  EXPECT_NE(coarse.output.find("--reference-resolution 16 is coarser than --resolutions' 32"), std::string::npos)
      << coarse.output;
  const CommandRun run = radmesh("bench accuracy furnace --cells 1,0.5 --reference-resolution 8");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--reference-resolution 8 is out of range"), std::string::npos) << run.output;
  // Every other value is checked before the references are solved too, not only the first.
  const std::string file = tempPath("a-file");
  std::ofstream(file) << "x";
  const std::map<std::string, std::string> cases = {
      {"--resolutions 32,5", "--resolutions 5 is out of range"},
      {"--reference-until nan", "--reference-until must be a convergence in (0, 1], e.g. 0.999; got nan"},
      {"--reference-until 2", "--reference-until must be a convergence in (0, 1]"},
      {"--out-dir " + file, "--out-dir '" + file + "': cannot make that folder"},
      {"--out-dir /proc/radmesh-nope", "--out-dir '/proc/radmesh-nope': cannot make that folder"},
      {"--json /proc/radmesh-nope/a.json", "--json '/proc/radmesh-nope/a.json': the folder '/proc/radmesh-nope' does "
                                           "not exist"},
      {"--subdivide off --element-rows share",
       "--element-rows shapes the elements, and --subdivide does not measure them: add uniform or adaptive"},
      {"--min-element 0.2", "--min-element shapes the elements"},  // off alone is the default
      {"--subdivide off,uniform --split-contrast 0.1",
       "--split-contrast shapes adaptive elements, and --subdivide does not measure them: add adaptive"},
      {"--json " + tempPath("a.txt"), "give a path ending in .json"},
  };
  for (const auto& [arguments, message] : cases) {
    const CommandRun refused = radmesh("bench accuracy furnace --cells 1 " + arguments);
    EXPECT_EQ(refused.exitCode, 2) << arguments << ": " << refused.output;
    EXPECT_NE(refused.output.find(message), std::string::npos) << arguments << ": " << refused.output;
    for (const char* solved : {"reference analytic", "reference hemicube"})
      EXPECT_EQ(refused.output.find(solved), std::string::npos) << arguments << ": refused before any solve";
  }
}

}  // namespace
}  // namespace radmesh

namespace radmesh {
namespace {

TEST(Cli, MeshBackendStatsCarryDepthsEmulatedTimeAndOpCountsForEveryMapping) {
  for (const std::string mapping : {"hierarchical", "cut-and-stack", "adaptive"}) {
    const std::string stats = tempPath("mesh-" + mapping + ".json");
    const CommandRun run = radmesh("solve cornell --preset paper --cell 0.1 --backend mesh --mapping " + mapping +
                                   " --resolution 64 --max-iterations 5 --until 1 --stats " + stats);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    std::ifstream in(stats);
    const auto j = nlohmann::json::parse(in);
    EXPECT_EQ(j["mapping"], mapping);
    EXPECT_NE(run.output.find("mesh: "), std::string::npos) << run.output;  // the machine's seconds, summed
    EXPECT_NE(run.output.find(" emulated MP-1 seconds ("), std::string::npos) << run.output;
    ASSERT_EQ(j["per_iteration"].size(), 5u);
    for (const auto& it : j["per_iteration"]) {
      for (const char* key : {"depth_a_max", "depth_b_max", "depth_a_hist", "depth_b_hist", "emulated_seconds", "passes",
                              "op_counts", "phases"})
        ASSERT_TRUE(it.contains(key)) << key;
      // The histograms count every one of the 4096 PEs, and their top bin is the max depth.
      int pes = 0;
      for (int count : it["depth_a_hist"]) pes += count;
      EXPECT_EQ(pes, 4096);
      EXPECT_EQ(it["depth_a_hist"].size(), it["depth_a_max"].get<size_t>() + 1);
      EXPECT_GE(it["depth_b_max"].get<int>(), 1);
      EXPECT_GT(it["emulated_seconds"].get<double>(), 0.0);
    }
  }
}

TEST(Cli, SolveStatsCarryTheEffectsPlanTheSolverApplied) {
  const std::string stats = tempPath("stats.json");
  for (const char* mode : {"auto", "all"}) {
    // At the paper's cell (54 patches; the default cell, chosen from the 1 m box, makes 1536).
    const CommandRun run = radmesh(std::string("solve furnace --cell 0.381 --preset paper --quiet --until 0.5 --effects ") +
                                   mode + " --stats " + stats);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    std::ifstream in(stats);
    const auto j = nlohmann::json::parse(in);
    const auto& e = j["effects"];
    for (const char* name : {"occlusion", "colour", "interreflection", "near field", "escape"}) {
      ASSERT_TRUE(e.contains(name)) << name << " in " << e.dump();
      EXPECT_FALSE(e[name]["reason"].get<std::string>().empty()) << name;
    }
    const bool all = std::string(mode) == "all";
    // The grey, closed, convex furnace: three skips, and the projection the solver really used.
    EXPECT_EQ(e["occlusion"]["on"].get<bool>(), all) << e.dump();
    EXPECT_EQ(e["colour"]["on"].get<bool>(), all);
    EXPECT_EQ(e["escape"]["on"].get<bool>(), all);
    EXPECT_TRUE(e["interreflection"]["on"].get<bool>());
    EXPECT_TRUE(e["near field"]["on"].get<bool>());  // walls meet at the box's edges
    EXPECT_NE(e["near field"]["reason"].get<std::string>().find("shooter-receiver pairs"), std::string::npos);
    EXPECT_EQ(j["projection"], all ? "plane" : "analytic");
    EXPECT_EQ(e["colour"]["reason"].get<std::string>().find("forced by --effects all") == 0, all);
    EXPECT_EQ(j["ledger"]["escaped"].get<double>(), 0.0);
  }
  const CommandRun bad = radmesh("solve furnace --effects some");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.output.find("--effects must be 'auto'"), std::string::npos) << bad.output;
}

}  // namespace
}  // namespace radmesh

namespace radmesh {
namespace {

// render --iterations N is --until 1 --until-unshot 0 --max-iterations N: given beside it, a stop was
// dropped without a word (--max-iterations 3 solved 5 iterations).
TEST(Cli, RenderIterationsRefusesTheStopsItSets) {
  const CommandRun probe = radmesh("render --help");
  if (probe.output.find("not built") != std::string::npos) GTEST_SKIP() << "radmesh was built without the viewer";
  EXPECT_NE(probe.output.find("--until 1 --until-unshot 0 --max-iterations N"), std::string::npos) << probe.output;
  for (const std::string stop : {"--max-iterations 3", "--until 0.9", "--until-unshot 0.1"}) {
    const CommandRun run = radmesh("render cornell --cell 0.1 --resolution 64 --iterations 5 " + stop +
                                   " --quiet --out " + tempPath("capped.png"));
    EXPECT_EQ(run.exitCode, 2) << stop << ": " << run.output;
    EXPECT_NE(run.output.find(" and --iterations cannot be given together: give one of them (radmesh render --help "
                              "says what each does)"),
              std::string::npos)
        << stop << ": " << run.output;
    EXPECT_FALSE(std::filesystem::exists(tempPath("capped.png"))) << stop;
  }
}

TEST(Cli, RenderSolvesOrReadsABakeAndWritesThePictureOfTheAskedSize) {
  const CommandRun probe = radmesh("render --help");
  if (probe.output.find("not built") != std::string::npos) GTEST_SKIP() << "radmesh was built without the viewer";
  const std::string solved = tempPath("solved.png"), bake = tempPath("bake.glb"), fromBake = tempPath("bake.png");
  const CommandRun run =
      radmesh("render cornell --cell 0.1 --resolution 64 --iterations 5 --size 160x120 --quiet --out " + solved);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(run.output.find("it/s"), std::string::npos) << run.output;  // --quiet: no progress
  // The exposure it chose, so that --exposure is not guesswork.
  EXPECT_NE(run.output.find(" EV (automatic; --exposure sets it)"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("5 iterations"), std::string::npos) << run.output;
  EXPECT_EQ(pngSize(solved), std::make_pair(160, 120));

  ASSERT_EQ(radmesh("solve cornell --cell 0.1 --resolution 64 --until 0.9 --quiet --out " + bake).exitCode, 0);
  // Solver options do not apply to a bake: each gets a warning, not silence.
  const CommandRun read =
      radmesh("render " + bake + " --resolution 64 --preset paper --strict --up y --size 96x64 --out " + fromBake);
  ASSERT_EQ(read.exitCode, 0) << read.output;
  EXPECT_NE(read.output.find("read bake"), std::string::npos) << read.output;
  EXPECT_NE(read.output.find("warning: --resolution does not apply"), std::string::npos) << read.output;
  EXPECT_NE(read.output.find("warning: --preset does not apply"), std::string::npos) << read.output;
  EXPECT_NE(read.output.find("warning: --strict does not apply"), std::string::npos) << read.output;
  EXPECT_EQ(read.output.find("--up does not apply"), std::string::npos) << read.output;  // a bake turns too
  EXPECT_EQ(read.output.find("--cell does not apply"), std::string::npos) << read.output;
  EXPECT_EQ(pngSize(fromBake), std::make_pair(96, 64));
}

// A lamp of 1e-25 lm/m^2 needs about +90 EV: the automatic exposure says so, and that can be given back.
TEST(Cli, RenderTakesBackTheExposureItChoseForAVeryDimScene) {
  const CommandRun probe = radmesh("render --help");
  if (probe.output.find("not built") != std::string::npos) GTEST_SKIP() << "radmesh was built without the viewer";
  const std::string scene = tempPath("dim.mgf"), bake = tempPath("dim.glb");
  std::ofstream(scene) << "m wall =\n c\n rd 0.5\nm lamp =\n c\n ed 1e-25\nv r1 =\n p 0 0 0\nv r2 =\n p 4 0 0\n"
                          "v r3 =\n p 4 4 0\nv r4 =\n p 0 4 0\nm wall\nprism r1 r2 r3 r4 -2.7\nv l1 =\n p 1.8 1.8 2.69\n"
                          "v l2 =\n p 1.8 2.2 2.69\nv l3 =\n p 2.2 2.2 2.69\nv l4 =\n p 2.2 1.8 2.69\nm lamp\nf l1 l2 l3 l4\n";
  ASSERT_EQ(radmesh("solve " + scene + " --cell 0.5 --resolution 32 --quiet --out " + bake).exitCode, 0);
  const CommandRun automatic = radmesh("render " + bake + " --size 80x60 --out " + tempPath("auto.png"));
  ASSERT_EQ(automatic.exitCode, 0) << automatic.output;
  const size_t at = automatic.output.find("exposure +");
  ASSERT_NE(at, std::string::npos) << automatic.output;
  const double ev = std::stod(automatic.output.substr(at + 9));
  EXPECT_GT(ev, 64.0);  // past the range --exposure took until 2026-12-04
  const CommandRun given =
      radmesh("render " + bake + " --size 80x60 --exposure " + fmt::format("{:.2f}", ev) + " --out " + tempPath("given.png"));
  EXPECT_EQ(given.exitCode, 0) << given.output;
  EXPECT_NE(given.output.find(fmt::format("exposure {:+.2f} EV (given", ev)), std::string::npos) << given.output;
}

// render ends its solve as solve does: Ctrl-C stops it at the end of the iteration (or round)
// under way, says that nothing was saved and how to keep the work, draws nothing and exits 130;
// --quiet keeps the warning of a solve stopped far from converged (not with --iterations, asked for).
TEST(Cli, RenderStopsOnCtrlCAndWarnsAsSolveDoes) {
  const CommandRun probe = radmesh("render --help");
  if (probe.output.find("not built") != std::string::npos) GTEST_SKIP() << "radmesh was built without the viewer";
  const std::string out = tempPath("interrupted.png");
  const std::string radmeshPath = (test::binaryDir() / "cli" / "radmesh").string();
  for (const auto& [cells, where] : {std::pair{"off", "iteration "}, std::pair{"auto", "round "}}) {
    const CommandRun run = runCommand("(" + radmeshPath + " render two-rooms --cell 0.1 --cells " + cells +
                                      " --quiet --out " + out + " & pid=$!; sleep 2; kill -INT $pid; wait $pid; echo exit $?)");
    EXPECT_NE(run.output.find("exit 130"), std::string::npos) << cells << ": " << run.output;
    EXPECT_NE(run.output.find(std::string("radmesh: interrupted after ") + where), std::string::npos) << run.output;
    EXPECT_NE(run.output.find(": nothing saved (no picture is drawn of a solve cut short; to keep a long solve's "
                              "work: radmesh solve SCENE --checkpoint FILE --out BAKE.glb, then render the bake)"),
              std::string::npos) << cells << ": " << run.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << cells;
  }
  const std::string farFrom = "warning: the solve stopped with 80.0% of the emitted power unshot";
  CommandRun run = radmesh("render office --quiet --max-iterations 10 --size 64x48 --out " + out);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find(farFrom + ", so its reflected light is far from converged (docs/accuracy.md); "
                                      "--max-iterations 10 stopped it"), std::string::npos) << run.output;
  run = radmesh("render office --quiet --iterations 10 --size 64x48 --out " + out);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(run.output.find("warning"), std::string::npos) << run.output;
}

TEST(Cli, RenderRefusesImpossibleViewsNamingTheOption) {
  const CommandRun probe = radmesh("render --help");
  if (probe.output.find("not built") != std::string::npos) GTEST_SKIP() << "radmesh was built without the viewer";
  const std::string out = tempPath("never.png");
  const std::map<std::string, std::string> cases = {
      {"--size 0x10", "--size"},
      {"--size 640", "--size"},
      {"--fov 180", "--fov"},
      {"--camera 1,2", "--camera"},
      {"--camera 0.2,0.2,0.2 --look 0.2,0.2,0.2", "radmesh: error: --camera/--look: "},  // not --fov, not given
      {"--camera 0.2,0.2,0.2 --look 0.2,0.2,0.2 --fov 90", "radmesh: error: --camera/--look/--fov: "},
      {"--camera 0.27799999713897705,0.274399995803833,0.27959999442100525", "(without --look, the scene's centre 0.278,0.2744,0.2796)"},
      {"--look nan,0,0", "--look"},
      {"--exposure nan", "--exposure nan is out of range"},
      {"--exposure 1e308", "--exposure 1e+308 is out of range"},
      {"--exposure -161", "--exposure -161 is out of range: give stops from -160 to 160"},
      {"--effects some", "--effects"},
      {"--fov 1e-308", "--fov must be from 0.01 to 170 degrees"},
      {"--fov 178", "--fov must be from 0.01 to 170 degrees (narrower, the picture's single-precision projection has no "
                    "pixels left; wider, the walls beside the eye fall before its near plane and the picture's sides "
                    "go black), got 178"},
      {"--camera 1e308,0,0", "--camera/--look: too far apart to aim the camera"},
  };
  for (const auto& [options, named] : cases) {
    const CommandRun run = radmesh("render cornell --cell 0.2 --iterations 1 " + options + " --out " + out);
    EXPECT_EQ(run.exitCode, 2) << options << ": " << run.output;
    EXPECT_NE(run.output.find(named), std::string::npos) << options << ": " << run.output;
    EXPECT_EQ(run.output.find("solved"), std::string::npos) << options << ": refused after the solve";
  }
  EXPECT_FALSE(std::filesystem::exists(out));
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)  // their shadow memory needs no ulimit -v
  // A picture beyond the memory the process may use (here capped by ulimit -v at 3 GB; 16384x16384
  // needs 5.6 GB) is refused before the solve, naming what fits.
  const CommandRun big = runCommand("ulimit -v 3000000 && " + (test::binaryDir() / "cli" / "radmesh").string() +
                                    " render cornell --cell 0.2 --iterations 1 --size 16384x16384 --out " + out);
  EXPECT_EQ(big.exitCode, 2) << big.output;
  EXPECT_NE(big.output.find("--size 16384x16384: drawing it needs about 5.6 GB, more than half of the 3.1 GB of memory "
                            "this process may use: give a smaller size (at most about 85"),
            std::string::npos)
      << big.output;
  EXPECT_EQ(big.output.find("solved"), std::string::npos) << big.output;
#endif
#ifdef RADMESH_HAS_VIEWER
  // A camera 12 m from the 0.55 m box, beyond the walk's far plane (10 m): the box is still drawn.
  const std::string far = tempPath("far.png");
  const CommandRun run = radmesh("render cornell --cell 0.2 --iterations 1 --camera 0.27,-12,0.27 --size 160x120 --out " + far);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Image picture = readPng(far);
  int drawn = 0;
  for (size_t i = 0; i < picture.rgba.size(); i += 4)
    drawn += !std::equal(picture.rgba.begin() + i, picture.rgba.begin() + i + 3, picture.rgba.begin());  // not as the corner
  EXPECT_GT(drawn, 4) << far;
  EXPECT_EQ(run.output.find("shows nothing of the model"), std::string::npos) << run.output;
  // Looking away from the box: a picture of the background alone, which used to come without a word.
  const CommandRun away = radmesh("render cornell --cell 0.2 --iterations 1 --camera 0.278,0.27,-0.8 --look "
                                  "0.278,0.27,-5 --size 80x60 --out " + far);
  ASSERT_EQ(away.exitCode, 0) << away.output;
  EXPECT_NE(away.output.find("warning: the picture shows nothing of the model"), std::string::npos) << away.output;
#endif
}

#ifdef RADMESH_HAS_VIEWER
// The bake shows what was solved: a room sealed off from the only lamp (inside a closed box) stays
// black. The display ambient term, which spreads the unshot power over every surface, drew it grey.
TEST(Cli, ABakeLightsNothingNoLightReaches) {
  const std::string scene = tempPath("sealed.mgf"), bake = tempPath("sealed.glb"), png = tempPath("sealed.png");
  std::ofstream(scene) << "m wall =\n c\n rd 0.5\nm lamp =\n c\n ed 1790\n"
                          "v r1 =\n p 0 0 0\nv r2 =\n p 4 0 0\nv r3 =\n p 4 4 0\nv r4 =\n p 0 4 0\n"
                          "v b1 =\n p 1 1 0.5\nv b2 =\n p 2 1 0.5\nv b3 =\n p 2 2 0.5\nv b4 =\n p 1 2 0.5\n"
                          "v c1 =\n p 1.001 1.001 0.501\nv c2 =\n p 1.999 1.001 0.501\n"
                          "v c3 =\n p 1.999 1.999 0.501\nv c4 =\n p 1.001 1.999 0.501\n"
                          "v l1 =\n p 1.4 1.4 1.49\nv l2 =\n p 1.4 1.6 1.49\nv l3 =\n p 1.6 1.6 1.49\n"
                          "v l4 =\n p 1.6 1.4 1.49\nm wall\nprism r1 r2 r3 r4 -2.7\nprism b4 b3 b2 b1 1\n"
                          "prism c1 c2 c3 c4 -0.998\nm lamp\nf l1 l2 l3 l4\n";
  ASSERT_EQ(radmesh("solve " + scene + " --cell 0.5 --quiet --out " + bake).exitCode, 0);
  const CommandRun run = radmesh("render " + bake + " --size 160x120 --out " + png);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const Image picture = readPng(png);
  int lit = 0;
  for (size_t i = 0; i < picture.rgba.size(); i += 4)
    lit += picture.rgba[i] + picture.rgba[i + 1] + picture.rgba[i + 2] > 0;
  EXPECT_EQ(lit, 0) << png;
}
#endif

#ifdef RADMESH_HAS_VIEWER
// A room 1e7 m from the origin bakes and draws as it does at the origin: the bake's float positions
// and the renderer's are taken about the model's centre (at 1e7 m a float snaps to whole metres:
// half the triangles lost their area, and the picture its shape).
TEST(Cli, ARoomFarFromTheOriginBakesAndDrawsAsAtTheOrigin) {
  const std::string room =
      "m wall =\n c\n rd 0.5\nm lamp =\n c\n ed 1790\nv r1 =\n p 0 0 0\nv r2 =\n p 4 0 0\nv r3 =\n p 4 4 0\n"
      "v r4 =\n p 0 4 0\nm wall\nprism r1 r2 r3 r4 -2.7\nv l1 =\n p 1.8 1.8 2.69\nv l2 =\n p 1.8 2.2 2.69\n"
      "v l3 =\n p 2.2 2.2 2.69\nv l4 =\n p 2.2 1.8 2.69\nm lamp\nf l1 l2 l3 l4\nv b1 =\n p 0.8 0.8 0\n"
      "v b2 =\n p 1.6 0.8 0\nv b3 =\n p 1.6 1.6 0\nv b4 =\n p 0.8 1.6 0\nm wall\nprism b4 b3 b2 b1 0.8\n";
  std::vector<Image> pictures;
  for (const std::string name : {"near", "far"}) {
    const std::string scene = tempPath(name + ".mgf"), bake = tempPath(name + ".glb"), png = tempPath(name + ".png");
    std::ofstream(scene) << (name == "far" ? "xf -t 1e7 0 0\n" + room + "xf\n" : room);
    ASSERT_EQ(radmesh("solve " + scene + " --cell 0.5 --resolution 64 --quiet --out " + bake).exitCode, 0);
    ASSERT_EQ(radmesh("render " + bake + " --size 160x120 --exposure 0 --out " + png).exitCode, 0);
    pictures.push_back(readPng(png));
  }
  ASSERT_EQ(pictures[0].rgba.size(), pictures[1].rgba.size());
  double difference = 0.0;
  for (size_t i = 0; i < pictures[0].rgba.size(); ++i)
    difference += std::abs(int(pictures[0].rgba[i]) - int(pictures[1].rgba[i]));
  EXPECT_LT(difference / double(pictures[0].rgba.size()), 0.5);  // levels a channel
}
#endif

// render simulates what solve does: only the effects the scene calls for, unless --effects all.
TEST(Cli, RenderSimulatesTheEffectsSolveDoes) {
  const CommandRun probe = radmesh("render --help");
  if (probe.output.find("not built") != std::string::npos) GTEST_SKIP() << "radmesh was built without the viewer";
  const std::string out = tempPath("furnace.png");
  for (const std::string mode : {"", " --effects auto", " --effects all"}) {
    const CommandRun run =
        radmesh("render furnace --cell 0.381 --preset paper --until 0.5 --size 64x48 --quiet" + mode + " --out " + out);
    ASSERT_EQ(run.exitCode, 0) << mode << run.output;
    // The grey, closed, convex furnace needs no occlusion: skipped unless forced.
    const bool all = mode == " --effects all";
    EXPECT_NE(run.output.find(all ? "occlusion       on" : "occlusion       off"), std::string::npos)
        << mode << run.output;
  }
}

// Stats as `radmesh solve --stats` writes them, with the figures `plot paper` reads: C 0.5, 0.96, 0.99, the
// last past the 0.95 the tables average to (`iterations` fewer: stopped short of it). `mapping` empty:
// the native solve of Table 1.3.
void writePaperStats(const std::string& path, int resolution, const std::string& mapping, int iterations = 3) {
  const bool mesh = !mapping.empty();
  nlohmann::json perIteration = nlohmann::json::array();
  const double convergence[] = {0.5, 0.96, 0.99}, emulated[] = {1.0, 3.0, 100.0}, depthA[] = {10, 20, 900};
  for (int i = 0; i < (mesh ? iterations : 13); ++i) {
    nlohmann::json it = {{"iteration", i + 1}, {"convergence", mesh ? convergence[i] : 0.5 + 0.01 * i},
                         {"seconds", 0.01}, {"reused_rows_total", i / 4}};
    if (mesh) it.update({{"emulated_seconds", emulated[i]}, {"depth_a_max", depthA[i]}, {"depth_b_max", 2 * depthA[i]}});
    perIteration.push_back(it);
  }
  nlohmann::json stats{{"backend", mesh ? "mesh" : "native"}, {"resolution", resolution}, {"per_iteration", perIteration}};
  if (mesh) stats["mapping"] = mapping;  // a native solve has none
  std::ofstream(path) << stats.dump();
}

void writeAllPaperStats(const std::string& folder) {
  std::filesystem::create_directories(folder);
  for (const std::string mapping : {"hierarchical", "cut-and-stack", "adaptive"})
    for (int n : {64, 128, 256})
      writePaperStats(folder + "/paper-test-" + mapping + "-" + std::to_string(n) + ".json", n, mapping);
  writePaperStats(folder + "/paper-test-reuse.json", 128, "");
}

#define SKIP_WITHOUT_GNUPLOT() \
  if (!gnuplotInstalled()) GTEST_SKIP() << "gnuplot is not installed (scripts/install-deps.sh installs it)"

TEST(Cli, PlotPaperGathersTheStatsIntoOneCsvAndDrawsFromIt) {
  SKIP_WITHOUT_GNUPLOT();
  const std::string stats = tempPath("stats"), csv = tempPath("paper-test.csv"), images = tempPath("images");
  writeAllPaperStats(stats);
  const CommandRun gathered = radmesh("plot paper test --stats " + stats + " --csv " + csv + " --images " + images);
  ASSERT_EQ(gathered.exitCode, 0) << gathered.output;
  EXPECT_EQ(readCsv(csv).size(), 1u + 9u * 3u + 13u);
  // Averages over the iterations up to the first at C >= 0.95: (1 + 3) / 2, (10 + 20) / 2, (20 + 40) / 2.
  EXPECT_NE(gathered.output.find("| cut-and-stack | 128x128 | 2 | 2.000 | 0.0100 | 15.0 | 30.0 |"), std::string::npos)
      << gathered.output;
  // Table 1.3 at the paper's iteration 13, which is also the last: 3 rows reused, C = 0.62.
  EXPECT_NE(gathered.output.find("| 13 | 3 | 62.00 |"), std::string::npos) << gathered.output;
  for (const std::string figure : {"convergence", "depth-a", "depth-b", "table11", "table12", "table13"})
    EXPECT_EQ(std::filesystem::exists(images + "/paper-test-" + figure + ".png"), gnuplotInstalled()) << figure;
  // Without --stats, the CSV alone gives the same tables.
  std::filesystem::remove_all(stats);
  const CommandRun redrawn = radmesh("plot paper test --csv " + csv + " --images " + images);
  ASSERT_EQ(redrawn.exitCode, 0) << redrawn.output;
  EXPECT_EQ(redrawn.output.substr(redrawn.output.find("Table 1.1")), gathered.output.substr(gathered.output.find("Table 1.1")));

  // The same table saved by a spreadsheet (a byte-order mark, Windows line ends, spaces after the
  // commas, a blank last line) gives the same tables; it used to have "no column".
  std::string text = readBytes(csv), saved = "\xEF\xBB\xBF";
  for (char c : text) saved += c == '\n' ? std::string("\r\n") : c == ',' ? std::string(", ") : std::string(1, c);
  const std::string spreadsheet = tempPath("spreadsheet.csv");
  std::ofstream(spreadsheet, std::ios::binary) << saved << "\r\n";
  const CommandRun reread = radmesh("plot paper test --csv " + spreadsheet + " --images " + images);
  ASSERT_EQ(reread.exitCode, 0) << reread.output;
  EXPECT_EQ(reread.output.substr(reread.output.find("Table 1.1")), gathered.output.substr(gathered.output.find("Table 1.1")));
  // A figure no measurement gives, and a column named twice, are refused naming the line and column.
  const size_t row = text.find("\nhierarchical,64,1,");
  ASSERT_NE(row, std::string::npos) << text;
  std::string nan = text;
  nan.replace(row + 1, std::string("hierarchical,64,1,0.5,").size(), "hierarchical,64,1,nan,");
  std::ofstream(csv) << nan;
  CommandRun run = radmesh("plot paper test --csv " + csv + " --images " + images);
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find(csv + ", line 2: 'nan' in column 'convergence' is not a finite number"), std::string::npos)
      << run.output;
  std::ofstream(csv) << "run,run" + text.substr(text.find(','));
  run = radmesh("plot paper test --csv " + csv + " --images " + images);
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find(csv + ": column 'run' appears twice in the header"), std::string::npos) << run.output;
}

TEST(Cli, PlotSaysWhichFileIsMissingOrWrong) {
  SKIP_WITHOUT_GNUPLOT();
  CommandRun run = radmesh("plot paper test --stats " + tempPath("none") + " --csv " + tempPath("p.csv") + " --images " +
                           tempPath("images"));
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("paper-test-hierarchical-64.json: cannot read"), std::string::npos) << run.output;
  run = radmesh("plot accuracy " + tempPath("nothing"));
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("nothing.csv: cannot read (No such file or directory); bench accuracy --out-dir DIR "
                            "--name NAME writes it"),
            std::string::npos)
      << run.output;
  const std::string bad = tempPath("bad");
  std::ofstream(bad + ".csv") << "projection,ratio,seconds_to_99\nplane,3\n";
  run = radmesh("plot accuracy " + bad);
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("bad.csv, line 2: 2 fields under a header of 3"), std::string::npos) << run.output;
  std::ofstream(bad + ".csv") << "projection,ratio,seconds_to_99\n";
  std::ofstream(bad + "-traces.csv") << "projection,ratio,resolution,cell_m,iteration\n";
  run = radmesh("plot accuracy " + bad);
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("bad.csv: a header and no rows: nothing to draw"), std::string::npos) << run.output;
  // A folder where the CSV belongs, or a file where the PNGs' folder belongs, is named as such.
  const std::string folder = tempPath("folder.csv");
  std::filesystem::create_directories(folder);
  run = radmesh("plot paper test --csv " + folder + " --images " + tempPath("images"));
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find(folder + ": is a folder, not a CSV file"), std::string::npos) << run.output;
  run = radmesh("plot paper test --csv " + bad + ".csv --images " + bad + ".csv");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--images '" + bad + ".csv': cannot make that folder"), std::string::npos) << run.output;
  // A missing input leaves no folder behind: the inputs are read first.
  const std::string images = tempPath("never"), plots = tempPath("never-plots");
  run = radmesh("plot paper test --csv " + tempPath("none.csv") + " --images " + images);
  EXPECT_EQ(run.exitCode, 2) << run.output;
  run = radmesh("plot scaling " + tempPath("none-model.csv") + " " + tempPath("none-ranks.csv") + " --png " + plots +
                "/x");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("none-model.csv: cannot read"), std::string::npos) << run.output;
  EXPECT_FALSE(std::filesystem::exists(images));
  EXPECT_FALSE(std::filesystem::exists(plots));
}

// Stats that are not what their names say, a run short of C = 0.95, and a --csv that would replace a
// stats file: each used to give a table (or a lost file) without a word.
TEST(Cli, PlotPaperChecksTheStatsAgainstTheirNames) {
  SKIP_WITHOUT_GNUPLOT();
  const std::string stats = tempPath("stats"), csv = tempPath("paper.csv"), images = tempPath("images");
  writeAllPaperStats(stats);
  const std::string plot = "plot paper test --stats " + stats + " --images " + images + " --csv ";
  const std::string reuse = stats + "/paper-test-reuse.json";
  CommandRun run = radmesh(plot + reuse);
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--csv"), std::string::npos) << run.output;
  EXPECT_NE(readBytes(reuse).find("per_iteration"), std::string::npos) << "the stats were replaced";

  const std::string cut = stats + "/paper-test-cut-and-stack-128.json";
  writePaperStats(cut, 128, "adaptive");
  run = radmesh(plot + csv);
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find(cut + ": the stats of a mesh solve, mapping adaptive, at 128, where its name says mesh, "
                                  "mapping cut-and-stack at 128"),
            std::string::npos)
      << run.output;

  writePaperStats(cut, 128, "cut-and-stack", 1);  // C = 0.5 when it stopped
  run = radmesh(plot + csv);
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("| cut-and-stack | 128x128 | 1+ | 1.000 |"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("warning: cut-and-stack at 128x128 stopped at C = 0.500"), std::string::npos) << run.output;
}

// `plot accuracy --out-dir DIR` draws a doc's figures into DIR (made if missing, in a folder that is not), leaving the
// committed ones beside the CSV as they were; a missing table leaves no folder behind.
TEST(Cli, PlotAccuracyDrawsIntoOutDirNotBesideTheCsv) {
  SKIP_WITHOUT_GNUPLOT();
  const std::filesystem::path docs = test::sourceDir() / "docs" / "data" / "accuracy";
  const auto committed = std::filesystem::last_write_time(docs / "cornell-error-vs-time.png");
  const std::string dir = tempPath("figures");
  CommandRun run = radmesh("plot accuracy " + (docs / "cornell.csv").string() + " --out-dir " + dir);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  for (const char* png : {"cornell-error-vs-time.png", "cornell-image-error-vs-time.png", "cornell-error-vs-convergence.png"}) {
    EXPECT_NE(run.output.find("drew " + dir + "/" + png + "\n"), std::string::npos) << run.output;
    EXPECT_GT(std::filesystem::file_size(dir + "/" + png), 1000u) << png;
  }
  EXPECT_EQ(run.output.find("drew " + docs.string()), std::string::npos) << run.output;
  EXPECT_EQ(std::filesystem::last_write_time(docs / "cornell-error-vs-time.png"), committed);
  const std::string never = tempPath("never");
  run = radmesh("plot accuracy " + tempPath("nothing") + " --out-dir " + never);
  EXPECT_NE(run.exitCode, 0) << run.output;
  EXPECT_FALSE(std::filesystem::exists(never));
}

// Drawing is all `plot` does: without gnuplot it fails, and a bench says it drew no plots; a PNG
// stem in a missing folder is refused before drawing (gnuplot used to write the PNG to standard output).
TEST(Cli, PlotFailsWithoutGnuplotAndRefusesAMissingFolderForItsPngs) {
  const std::string binary = (test::binaryDir() / "cli" / "radmesh").string();
  CommandRun run = runCommand("PATH=/nonexistent " + binary + " plot accuracy " + tempPath("any"));
  EXPECT_EQ(run.exitCode, 1) << run.output;
  EXPECT_NE(run.output.find("gnuplot is not installed"), std::string::npos) << run.output;
  const std::string dir = tempPath("bench");
  run = runCommand("PATH=/nonexistent " + binary +
                   " bench accuracy furnace --cells 1 --resolutions 16 --projections hemicube --reference-resolution 32 "
                   "--threads 1 --out-dir " + dir);
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("wrote " + dir + "/furnace.csv, " + dir + "/furnace-traces.csv\n"), std::string::npos)
      << run.output;
  EXPECT_EQ(run.output.find("and the plots"), std::string::npos) << run.output;

  SKIP_WITHOUT_GNUPLOT();
  const std::string data = (test::sourceDir() / "docs" / "data" / "scaling").string();
  const std::string missing = tempPath("missing/folder/scaling");
  run = radmesh("plot scaling " + data + "/np1-model.csv " + data + "/np1-ranks.csv " + data + "/np2-ranks.csv --png " + missing);
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--png '" + missing + "': the folder '" + tempPath("missing/folder") + "' does not exist"),
            std::string::npos) << run.output;
  EXPECT_FALSE(std::filesystem::exists(tempPath("missing")));
  const std::string stem = tempPath("scaling");
  run = radmesh("plot scaling " + data + "/np1-model.csv " + data + "/np1-ranks.csv " + data + "/np2-ranks.csv --png " + stem);
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_TRUE(std::filesystem::exists(stem + "-speedup.png")) << run.output;
  EXPECT_EQ(run.output.find("PNG"), std::string::npos) << "PNG bytes on standard output";

  // A run missing a rank's row, or of another setting than the model's, was drawn as measured.
  const std::string two = readBytes(data + "/np2-ranks.csv");
  const std::string half = tempPath("half-ranks.csv"), other = tempPath("other-ranks.csv");
  std::ofstream(half) << two.substr(0, two.find('\n', two.find('\n') + 1) + 1);  // the header and rank 0
  std::string relabelled = two;
  for (size_t at = relabelled.find("hemicube,32,"); at != std::string::npos; at = relabelled.find("hemicube,32,", at))
    relabelled.replace(at, 12, "plane,64,");
  std::ofstream(other) << relabelled;
  const std::string plot = "plot scaling " + data + "/np1-model.csv " + data + "/np1-ranks.csv ";
  run = radmesh(plot + half + " --png " + stem);
  EXPECT_EQ(run.exitCode, 1) << run.output;
  EXPECT_NE(run.output.find("the 2-rank run has rows for 1 rank(s) where it needs one for each of 0 to 1"),
            std::string::npos)
      << run.output;
  run = radmesh(plot + other + " --png " + stem);
  EXPECT_EQ(run.exitCode, 1) << run.output;
  EXPECT_NE(run.output.find(other + ", line 2: a run of plane,64,1, where the model"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace radmesh

namespace radmesh {
namespace {

// k shooters per iteration: half the iterations for k = 2, and the emulated MP-1 time only on the mesh.
TEST(Cli, BenchSolveTimesEveryShooterCountOnEitherBackEnd) {
  for (const std::string backend : {"native", "mesh"}) {
    const auto j = runBench("solve cornell --cell 0.1 --backend " + backend +
                            " --projections plane --resolutions 64 --shooters 1,2 --until 0.9").json;
    ASSERT_EQ(j["rows"].size(), 2u) << j.dump();
    EXPECT_EQ(j["rows"][0]["shooters"], 1);
    EXPECT_EQ(j["rows"][1]["shooters"], 2);
    const int one = j["rows"][0]["iterations_to_until"], two = j["rows"][1]["iterations_to_until"];
    EXPECT_LE(two, (one + 1) / 2 + 1) << j.dump();
    for (const auto& row : j["rows"]) {
      EXPECT_GT(row["ms_per_iteration"].get<double>(), 0.0);
      EXPECT_EQ(row["emulated_seconds_per_iteration"].get<double>() > 0.0, backend == "mesh") << row.dump();
    }
  }
}

}  // namespace
}  // namespace radmesh

namespace radmesh {
namespace {

// With no solver options, `solve` gives what docs/accuracy.md recommends for a bake: the hemicube
// at 256², until at most 1 % of the emitted power is unshot, and the unshot power at every
// iteration. The Cornell box on a 10 cm grid (--cell is not the preset's) takes 793 iterations,
// the office 7929 (two minutes under ASan).
// Light a balanced ledger lost where no solve should lose it is warned of: all of a lamp a
// nanometre from a wall went past it, and the paper's plane, solved on, misses a seventh of the box's
// light. A bake of the box loses nothing it should not.
TEST(Cli, LightLostWhereNoSolveLosesItIsWarnedOf) {
  const std::string scene = tempPath("near-wall.mgf");
  std::ofstream(scene) << "m wall =\n c\n rd 0.5\nv r1 =\n p 0 0 0\nv r2 =\n p 4 0 0\nv r3 =\n p 4 4 0\n"
                          "v r4 =\n p 0 4 0\nm wall\nprism r1 r2 r3 r4 -2.7\nm lamp =\n c\n ed 1790\n"
                          "v l1 =\n p 1e-9 1.8 1.0\nv l2 =\n p 1e-9 1.8 1.4\nv l3 =\n p 1e-9 2.2 1.4\n"
                          "v l4 =\n p 1e-9 2.2 1.0\nm lamp\nf l1 l2 l3 l4\n";
  CommandRun run = radmesh("solve " + scene + " --cell 0.5 --quiet");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  // The lamp lies on the wall, which closes its edges: the room is closed.
  EXPECT_NE(run.output.find("warning: 100.0% of the power left a closed scene or never entered it"), std::string::npos)
      << run.output;
  run = radmesh("solve cornell --preset paper --until 1 --until-unshot 0.01 --quiet");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("warning: the single plane missed 14."), std::string::npos) << run.output;
  run = radmesh("solve cornell --cell 0.1 --quiet");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(run.output.find("warning"), std::string::npos) << run.output;
}

// A closed black 2 m box at x0, lit by a 0.4 m panel under its ceiling; `insideOut` turns every
// wall's front outward, so that all the panel's light falls on backs.
std::string blackBox(double x0, bool insideOut) {
  std::string mgf;
  auto v = [&](const std::string& name, double x, double y, double z) {
    mgf += fmt::format("v {} =\n p {} {} {}\n", name, x0 + x, y, z);
  };
  const std::string b = fmt::format("b{}", x0);
  for (int i = 0; i < 8; ++i) v(b + std::to_string(i), (i == 1 || i == 2 || i == 5 || i == 6) ? 2 : 0, (i % 4) >= 2 ? 2 : 0, i >= 4 ? 2 : 0);
  const char* faces[] = {"0 1 2 3", "4 7 6 5", "0 4 5 1", "1 5 6 2", "2 6 7 3", "3 7 4 0"};  // fronts inward
  mgf += "m black\n";
  for (const char* face : faces) {
    std::istringstream in(face);
    std::vector<std::string> corners;
    for (std::string c; in >> c;) corners.push_back(b + c);
    if (insideOut) std::reverse(corners.begin(), corners.end());
    mgf += "f";
    for (const std::string& c : corners) mgf += " " + c;
    mgf += "\n";
  }
  v(b + "l0", 0.8, 0.8, 1.99), v(b + "l1", 1.2, 0.8, 1.99), v(b + "l2", 1.2, 1.2, 1.99), v(b + "l3", 0.8, 1.2, 1.99);
  return mgf + fmt::format("m light\nf {0}l0 {0}l3 {0}l2 {0}l1\n", b);
}

// Light on the backs of one-sided surfaces is part of absorbed, and said as such on the ledger
// line and in the stats. Two black boxes with equal lights, one inside out: exactly half of the
// power falls on backs (black walls reflect nothing back onto the lights' own backs), and that is
// warned of; the box the right way out alone puts none there.
TEST(Cli, LightOnBackFacesIsSaidInTheLedgerAndWarnedOf) {
  const std::string materials = "m black =\n c\n rd 0\nm light =\n c\n ed 100\n";
  const std::string both = tempPath("both.mgf"), one = tempPath("one.mgf"), stats = tempPath("stats.json");
  std::ofstream(both) << materials << blackBox(0, false) << blackBox(4, true);
  std::ofstream(one) << materials << blackBox(0, false);
  CommandRun run = radmesh("solve " + both + " --cell 0.5 --resolution 32 --quiet --stats " + stats);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const auto l = readJson(stats)["ledger"];
  const double emitted = l["emitted"].get<double>(), back = l["absorbed_by_back_faces"].get<double>();
  EXPECT_NEAR(back / emitted, 0.5, 1e-6) << l.dump();
  EXPECT_NEAR(l["absorbed"].get<double>(), emitted, 1e-6 * emitted) << l.dump();
  EXPECT_NE(run.output.find(fmt::format("= absorbed {:.6g} ({:.6g} on back faces) + unshot", l["absorbed"].get<double>(), back)),
            std::string::npos) << run.output;
  EXPECT_NE(run.output.find("warning: 50.0% of the emitted power was absorbed on the backs of one-sided surfaces"),
            std::string::npos) << run.output;
  EXPECT_NE(run.output.find("give it thickness, or in glTF make its material doubleSided"), std::string::npos) << run.output;
  run = radmesh("solve " + one + " --cell 0.5 --resolution 32 --quiet --stats " + stats);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(readJson(stats)["ledger"]["absorbed_by_back_faces"].get<double>(), 0.0);
  EXPECT_NE(run.output.find(" (0 on back faces) + unshot"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("warning"), std::string::npos) << run.output;
}

TEST(Cli, SolveByDefaultBakesToAtMostOnePercentUnshot) {
  const std::string stats = tempPath("stats.json");
  const CommandRun run = radmesh("solve cornell --cell 0.1 --quiet --stats " + stats);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(run.output.find("warning"), std::string::npos) << run.output;
  std::ifstream in(stats);
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["projection"], "hemicube");
  EXPECT_EQ(j["resolution"], 256);
  EXPECT_EQ(j["until_unshot"], 0.01);
  EXPECT_LE(j["unshot_fraction"].get<double>(), 0.01);
  // The stopping rule stopped it at the first iteration at or below 1 %, not earlier or later.
  const auto& it = j["per_iteration"];
  ASSERT_GE(it.size(), 2u);
  EXPECT_GT(it[it.size() - 2]["unshot_fraction"].get<double>(), 0.01);
  EXPECT_EQ(it.back()["unshot_fraction"], j["unshot_fraction"]);
  for (size_t i = 1; i < it.size(); ++i)  // shooting only ever passes on part of what was unshot
    ASSERT_LT(it[i]["unshot_fraction"].get<double>(), it[i - 1]["unshot_fraction"].get<double>()) << i;
}

TEST(Cli, PresetPaperGivesThePapersSettingsAndExplicitFlagsWin) {
  const std::string stats = tempPath("stats.json");
  CommandRun run = radmesh("solve cornell --cell 0.1 --quiet --preset paper --stats " + stats);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  auto j = nlohmann::json::parse(std::ifstream(stats));
  EXPECT_EQ(j["projection"], "plane");
  EXPECT_EQ(j["resolution"], 128);
  EXPECT_EQ(j["ratio"], 3.0);
  EXPECT_EQ(j["shooters"], 1);
  EXPECT_EQ(j["until"], 0.95);
  EXPECT_EQ(j["until_unshot"], 0.0);
  // C = 0.95 leaves most of the Cornell box's light unshot, and the solve says so.
  EXPECT_GT(j["unshot_fraction"].get<double>(), 0.1);
  EXPECT_NE(run.output.find("warning: the solve stopped with"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("catches only"), std::string::npos) << run.output;  // the paper's plane is fine
  // A narrower plane loses most of each shot, and the solve says so.
  run = radmesh("solve cornell --cell 0.1 --quiet --preset paper --ratio 0.5 --max-iterations 2");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("warning: the plane catches only 23.9% of each shot, and what it misses is lost "
                            "(\"not captured\" in the ledger); --ratio 3, the paper's, catches 91.7%"),
            std::string::npos)
      << run.output;
  // Flags beside the preset win, before or after it.
  run = radmesh("solve cornell --cell 0.1 --quiet --until 0.5 --preset paper --resolution 64 --stats " + stats);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  j = nlohmann::json::parse(std::ifstream(stats));
  EXPECT_EQ(j["projection"], "plane");
  EXPECT_EQ(j["resolution"], 64);
  EXPECT_EQ(j["until"], 0.5);
  // The mesh back end runs the single plane alone: the default bake takes it rather than failing,
  // while an explicit hemicube is still refused.
  run = radmesh("solve cornell --cell 0.1 --quiet --backend mesh --max-iterations 2 --stats " + stats);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(nlohmann::json::parse(std::ifstream(stats))["projection"], "plane");
  run = radmesh("solve cornell --quiet --backend mesh --projection hemicube --max-iterations 2");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("is native only"), std::string::npos) << run.output;
  run = radmesh("solve cornell --preset fast");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--preset 'fast' is unknown"), std::string::npos) << run.output;
}

// --preset elements: the bake, but patches 2.625 times the scene's cell (rounded) shoot onto uniform
// elements a quarter of theirs; flags beside it win.
TEST(Cli, PresetElementsShootsFromCoarserPatchesOntoElements) {
  const std::string stats = tempPath("stats.json");
  CommandRun run = radmesh("solve cornell --quiet --preset elements --stats " + stats);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("cell 0.09 m, --preset elements' 2.625 x the scene's, rounded: cell 0.0343 m, a "
                            "sixteenth of the model's smallest extent"),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("min element 0.0225 m, a quarter of the cell"), std::string::npos) << run.output;
  auto j = nlohmann::json::parse(std::ifstream(stats));
  EXPECT_EQ(j["projection"], "hemicube");
  EXPECT_EQ(j["resolution"], 256);
  EXPECT_EQ(j["subdivide"], "uniform");
  EXPECT_EQ(j["until"], 1.0);
  EXPECT_EQ(j["until_unshot"], 0.01);
  EXPECT_LE(j["unshot_fraction"].get<double>(), 0.01);
  EXPECT_EQ(j["patches"], 343);
  EXPECT_EQ(j["elements"], 6017);
  EXPECT_NEAR(j["min_element"].get<double>(), 0.0225, 1e-15);
  // --cell sets the patches, and the elements follow --min-element when given.
  run = radmesh("solve cornell --quiet --min-element 0.05 --preset elements --cell 0.1 --resolution 64 "
                "--max-iterations 2 --stats " + stats);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(run.output.find("min element"), std::string::npos) << run.output;
  j = nlohmann::json::parse(std::ifstream(stats));
  EXPECT_EQ(j["patches"], 272);
  EXPECT_EQ(j["min_element"], 0.05);
  EXPECT_EQ(j["resolution"], 64);
  run = radmesh("solve cornell --quiet --subdivide off --preset elements --max-iterations 2 --stats " + stats);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  j = nlohmann::json::parse(std::ifstream(stats));
  EXPECT_EQ(j["subdivide"], "off");
  EXPECT_EQ(j["elements"], j["patches"]);
}

// What the reader repaired is listed by info, and --strict makes each repair an error on every command.
TEST(Cli, StrictRefusesAFileThatNeededRepairs) {
  const std::string file = std::string(RADMESH_SOURCE_DIR) + "/tests/data/repaired/mgf_unknown_entity.mgf";
  CommandRun run = radmesh("info " + file + " --json");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const auto warnings = nlohmann::json::parse(run.output.substr(run.output.find('{')))["warnings"];
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].get<std::string>().find("unknown entity"), std::string::npos) << warnings;
  for (const std::string& command : {"info " + file + " --strict", "solve " + file + " --strict --quiet",
                                     "render " + file + " --strict --quiet --out " + tempPath("strict.png")}) {
    run = radmesh(command);
    EXPECT_EQ(run.exitCode, 2) << command << run.output;
    EXPECT_NE(run.output.find(file + ": refused under --strict (each warning an error), for its 2 warnings:\n  line "),
              std::string::npos)
        << run.output;
    EXPECT_NE(run.output.find("(fix: correct what the warnings name, or leave --strict out to open it as warned)"),
              std::string::npos)
        << run.output;
  }
}

// info --cells: each room with its patches, emitters and power, which add up to the scene's, and the
// portals between them, as JSON and as text; --cell-groups shapes them.
TEST(Cli, InfoCellsListsTheRoomsAndThePortalsAsJson) {
  const CommandRun run = radmesh("info two-rooms --cells --json");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const auto j = nlohmann::json::parse(run.output);
  ASSERT_EQ(j["cells"].size(), 2u) << j["cells"].dump();
  ASSERT_EQ(j["portals"].size(), 1u) << j["portals"].dump();
  long patches = j["outside_patches"].get<long>(), emitters = 0;
  double emitted = 0.0;
  for (const auto& cell : j["cells"]) {
    for (const char* key : {"name", "patches", "area_m2", "emitters", "emitted_w"})
      EXPECT_TRUE(cell.contains(key)) << key << " in " << cell.dump();
    patches += cell["patches"].get<long>();
    emitters += cell["emitters"].get<long>();
    emitted += cell["emitted_w"].get<double>();
  }
  EXPECT_EQ(patches, j["patches"].get<long>());
  EXPECT_EQ(emitters, j["emitter_patches"].get<long>());
  EXPECT_NEAR(emitted, j["emitted_power"].get<double>(), 1e-9);
  EXPECT_EQ(j["portals"][0]["cells"], nlohmann::json::array({0, 1}));
  EXPECT_NEAR(j["portals"][0]["area_m2"].get<double>(), 0.9 * 2.1, 1e-9);

  const CommandRun text = radmesh("info building:1x1 --cells");
  ASSERT_EQ(text.exitCode, 0) << text.output;
  EXPECT_NE(text.output.find("3 (found in"), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("2 portals"), std::string::npos) << text.output;
  for (const char* name : {"r0c0", "corridor 0", "spine"}) EXPECT_NE(text.output.find(name), std::string::npos) << name;

  // Rooms of different names stay apart when groups join; a value it does not know is refused.
  const CommandRun join = radmesh("info two-rooms --cells --cell-groups join --json");
  ASSERT_EQ(join.exitCode, 0) << join.output;
  EXPECT_EQ(nlohmann::json::parse(join.output)["cells"].size(), 2u);
  const CommandRun bad = radmesh("info two-rooms --cells --cell-groups merge");
  EXPECT_NE(bad.exitCode, 0);
  EXPECT_NE(bad.output.find("--cell-groups"), std::string::npos) << bad.output;
}

// info --cells takes auto|off as the solving commands' --cells does: "--cells auto" was one argument
// too many. Alone it still means auto, before the scene too.
TEST(Cli, InfoCellsTakesAutoOrOff) {
  const auto cellsOf = [](const std::string& arguments) {
    const CommandRun run = radmesh("info " + arguments + " --json");
    EXPECT_EQ(run.exitCode, 0) << arguments << ": " << run.output;
    nlohmann::json j = nlohmann::json::parse(run.output, nullptr, false);
    return j.is_object() && j.contains("cells") ? nlohmann::json{j["cells"], j["portals"]} : nlohmann::json();
  };
  const nlohmann::json alone = cellsOf("two-rooms --cells");
  ASSERT_EQ(alone[0].size(), 2u) << alone.dump();
  ASSERT_EQ(alone[1].size(), 1u) << alone.dump();
  for (const std::string arguments : {"two-rooms --cells auto", "two-rooms --cells=auto", "--cells auto two-rooms",
                                      "--cells two-rooms"})
    EXPECT_EQ(cellsOf(arguments), alone) << arguments;
  EXPECT_EQ(cellsOf("two-rooms --cells off"), nlohmann::json()) << "off lists no cells";
  EXPECT_EQ(cellsOf("--cells off two-rooms"), nlohmann::json());
  CommandRun run = radmesh("info two-rooms --cells off --cell-groups join");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--cell-groups requires --cells"), std::string::npos) << run.output;
  run = radmesh("info two-rooms --cells maybe");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_EQ(run.output, "radmesh: error: --cells 'maybe' is unknown: give auto (list the cells and portals, as "
                        "--cells alone does) or off\n");
}

TEST(Cli, InfoPlanDrawsThePlanOrSaysWhatIsWrong) {
  const std::string plan = tempPath("plan.png");
  const CommandRun run = radmesh("info building:1x1 --plan " + plan + " --json");
  if (run.output.find("built without") != std::string::npos) GTEST_SKIP() << "radmesh was built without the viewer";
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const auto j = nlohmann::json::parse(run.output);
  EXPECT_EQ(j["cells"].size(), 3u);
  // The long side 1000 px, the other in proportion, 20 px margins (viewer/cell_plan.h).
  const double dx = j["bounds_max"][0].get<double>() - j["bounds_min"][0].get<double>();
  const double dy = j["bounds_max"][1].get<double>() - j["bounds_min"][1].get<double>();
  const double scale = 1000.0 / std::max(dx, dy);
  EXPECT_EQ(pngSize(plan), std::make_pair(int(std::lround(dx * scale)) + 40, int(std::lround(dy * scale)) + 40));
  // It says what it wrote, as every command that writes does: last in the text, in the JSON as "plan".
  EXPECT_EQ(j["plan"], plan);
  const CommandRun text = radmesh("info building:1x1 --plan " + plan);
  ASSERT_EQ(text.exitCode, 0) << text.output;
  EXPECT_TRUE(text.output.ends_with("\nwrote " + plan + "\n")) << text.output;
  const CommandRun bad = radmesh("info two-rooms --plan " + tempPath("plan.jpg"));
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  EXPECT_NE(bad.output.find("--plan"), std::string::npos) << bad.output;
  const CommandRun size = radmesh("info building:0x3");
  EXPECT_EQ(size.exitCode, 2) << size.output;
  EXPECT_NE(size.output.find("building:COLSxROWS"), std::string::npos) << size.output;
}

TEST(Cli, OutputPathsAreCheckedBeforeTheSolve) {
  const std::string folder = tempPath("no-such-folder");
  const std::string missing = folder + "/x";
  const std::string refused = "': the folder '" + folder + "' does not exist: create it (mkdir -p " + folder + ")";
  const std::map<std::string, std::string> cases = {
      {"solve office --out " + missing + ".glb", "--out '" + missing + ".glb" + refused},
      {"solve office --out " + tempPath("x.png"), "give a path ending in .glb"},
      {"solve office --stats " + missing + ".json", "--stats '" + missing + ".json" + refused},
      {"solve office --stats " + tempPath("x.txt"), "give a path ending in .json"},
      {"solve office --checkpoint " + missing + ".ckpt", "--checkpoint '" + missing + ".ckpt" + refused},
      {"info building:3x3 --plan " + missing + ".png", "--plan '" + missing + ".png" + refused},
      // Every output alike: a missing folder is refused, not made (bench's used to be).
      {"bench solve furnace --json " + missing + ".json", "--json '" + missing + ".json" + refused},
      {"bench solve furnace --csv " + missing, "--csv '" + missing + refused},
      {"bench cells two-rooms --json " + missing + ".json", "--json '" + missing + ".json" + refused},
      {"bench accuracy furnace --quick --json " + missing + ".json", "--json '" + missing + ".json" + refused},
      // A folder of outputs is made, as a file is, in a folder that exists.
      {"bench accuracy furnace --quick --out-dir " + missing, "--out-dir '" + missing + refused},
  };
  for (const auto& [arguments, message] : cases) {
    const CommandRun run = radmesh(arguments);
    EXPECT_EQ(run.exitCode, 2) << arguments << ": " << run.output;
    EXPECT_NE(run.output.find(message), std::string::npos) << arguments << ": " << run.output;
    EXPECT_EQ(run.output.find("solving"), std::string::npos) << arguments << ": " << run.output;
  }
  EXPECT_FALSE(std::filesystem::exists(folder));
  // A folder named like the file: refused before, not after, the solve.
  const std::string named = tempPath("folder.json");
  std::filesystem::create_directories(named);
  CommandRun run = radmesh("solve furnace --stats " + named);
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--stats '" + named + "' is a folder"), std::string::npos) << run.output;
  run = radmesh("solve furnace --checkpoint " + named);
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--checkpoint '" + named + "' is a folder"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("solving"), std::string::npos) << run.output;
  run = radmesh("solve furnace --resume " + named);
  EXPECT_NE(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("is a folder, not a checkpoint"), std::string::npos) << run.output;
  if (radmesh("render --help").output.find("not built") != std::string::npos) return;
  // /proc takes no new file: found before the solve (it failed after it, the work lost).
  for (const std::string& out : {missing + ".png", tempPath("x.jpg"), std::string("/proc/radmesh.png")}) {
    const CommandRun run = radmesh("render office --out " + out);
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("--out '" + out + "'"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("solved"), std::string::npos) << run.output;
  }
}

// An output path whose file name is its extension alone ("--out .glb") would write a hidden file
// with no name: every option that writes a file refuses it, naming the option and a path to give,
// before any work and without writing anything.
TEST(Cli, AnOutputNamedOnlyByItsExtensionIsRefused) {
  const std::string dir = std::filesystem::path(tempPath("x")).parent_path().string();
  const std::string binary = (test::binaryDir() / "cli" / "radmesh").string();
  const std::pair<std::string, std::string> cases[] = {
      {"solve office --out .glb", "--out '.glb': the file name is only the extension, which would write a hidden file "
                                  "named .glb: give a name before it (e.g. NAME.glb)"},
      {"solve office --stats out/.JSON", "--stats 'out/.JSON': the file name is only the extension, which would write "
                                         "a hidden file named .JSON: give a name before it (e.g. out/NAME.json)"},
      {"info office --plan .png", "--plan '.png': the file name is only the extension"},
      {"bench solve furnace --resolutions 16 --json .json", "--json '.json': the file name is only the extension"},
      {"bench accuracy furnace --quick --json .json", "--json '.json': the file name is only the extension"},
      {"render office --out .png", "--out '.png': the file name is only the extension"},
      // Options that take any name: one dot, leading, is a hidden file all the same.
      {"solve office --checkpoint .ckpt", "--checkpoint '.ckpt': the file name is only the extension, which would "
                                          "write a hidden file named .ckpt: give a name before it (e.g. NAME.ckpt)"},
      {"solve office --checkpoint out/.ckpt", "--checkpoint 'out/.ckpt': the file name is only the extension"},
      {"bench solve furnace --csv .scaling", "--csv '.scaling': the file name is only the extension"},
  };
  for (const auto& [arguments, message] : cases) {
    if (arguments.starts_with("render") && radmesh("render --help").output.find("not built") != std::string::npos) continue;
    const CommandRun run = runCommand("cd " + dir + " && " + binary + " " + arguments);
    EXPECT_EQ(run.exitCode, 2) << arguments << ": " << run.output;
    EXPECT_NE(run.output.find("radmesh: error: " + message), std::string::npos) << arguments << ": " << run.output;
    EXPECT_EQ(run.output.find("solving"), std::string::npos) << arguments << ": " << run.output;
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir)) << "a file was written in " << dir;
}

// Two outputs on one file, or an output on the scene, would lose one of them without a word.
TEST(Cli, OutputsThatWouldReplaceTheSceneOrEachOtherAreRefused) {
  const std::string scene = tempPath("room.gltf");
  std::filesystem::copy_file(test::sourceDir() / "assets" / "cornell.gltf", scene);
  const std::string before = readBytes(scene);
  const std::string dir = std::filesystem::path(scene).parent_path().string();
  const std::map<std::string, std::string> cases = {
      {"solve " + scene + " --checkpoint " + dir + "/../" + std::filesystem::path(dir).filename().string() +
           "/room.gltf",
       "is the scene being solved: writing it would replace the scene"},
      {"solve furnace --checkpoint " + tempPath("same.glb") + " --out " + tempPath("same.glb"),
       "--checkpoint '" + tempPath("same.glb") + "' is the file --out writes too"},
      {"solve furnace --stats " + tempPath("s.json") + " --checkpoint " + tempPath("s.json"),
       "--checkpoint '" + tempPath("s.json") + "' is the file --stats writes too"},
  };
  for (const auto& [arguments, message] : cases) {
    const CommandRun run = radmesh(arguments + " --max-iterations 2");
    EXPECT_EQ(run.exitCode, 2) << arguments << ": " << run.output;
    EXPECT_NE(run.output.find(message), std::string::npos) << arguments << ": " << run.output;
    EXPECT_EQ(run.output.find("solving"), std::string::npos) << arguments << ": " << run.output;
  }
  EXPECT_NE(radmesh("solve " + scene + " --checkpoint " + scene).output.find("is the scene being solved"),
            std::string::npos);
  // A link named as a picture that leads to the scene: render and info --plan wrote through it.
  const std::string link = tempPath("link.png");
  std::filesystem::create_symlink(scene, link);
  for (const std::string& arguments : {"render " + scene + " --cell 0.2 --iterations 2 --out " + link,
                                      "info " + scene + " --plan " + link}) {
    const CommandRun run = radmesh(arguments);
    EXPECT_EQ(run.exitCode, 2) << arguments << ": " << run.output;
    EXPECT_NE(run.output.find("'" + link + "' is the scene being solved"), std::string::npos) << run.output;
  }
  EXPECT_EQ(readBytes(scene), before);
  // Going on from a checkpoint and saving it again in place stays allowed.
  const std::string checkpoint = tempPath("c.ckpt");
  ASSERT_EQ(radmesh("solve furnace --max-iterations 2 --checkpoint " + checkpoint).exitCode, 0);
  const CommandRun again = radmesh("solve furnace --max-iterations 4 --checkpoint " + checkpoint + " --resume " + checkpoint);
  EXPECT_EQ(again.exitCode, 0) << again.output;
}

}  // namespace
}  // namespace radmesh
