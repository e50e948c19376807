// Option values read as the user wrote them, and warnings that name what the user set.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "tests/cli/cli_run.h"
#include "tests/test_paths.h"

namespace radmesh {
namespace {

nlohmann::json statsOf(const std::string& arguments) {
  const std::string stats = tempPath("stats.json");
  const CommandRun run = radmesh(arguments + " --quiet --stats " + stats);
  EXPECT_EQ(run.exitCode, 0) << arguments << ": " << run.output;
  return nlohmann::json::parse(std::ifstream(stats));
}

// CLI11 reads whole numbers with strtoll's base 0: 064 was octal 52, 0100 was 64.
TEST(OptionValues, WholeNumbersAreDecimalWhateverTheirLeadingZeros) {
  nlohmann::json j = statsOf("solve furnace --resolution 064 --max-iterations 0100");
  EXPECT_EQ(j["resolution"], 64);
  EXPECT_EQ(j["iterations"], 100);
  j = statsOf("solve furnace --resolution=0128 --max-iterations=007");
  EXPECT_EQ(j["resolution"], 128);
  EXPECT_EQ(j["iterations"], 7);
  // A list, and a scene whose name only looks like a number is left as it is.
  const CommandRun bench = radmesh("bench solve furnace --projections plane --resolutions 016,032 --max-iterations 02");
  EXPECT_EQ(bench.exitCode, 0) << bench.output;
  EXPECT_NE(bench.output.find("\nplane          16    1 "), std::string::npos) << bench.output;
  EXPECT_NE(bench.output.find("\nplane          32    1 "), std::string::npos) << bench.output;
  EXPECT_NE(bench.output.find("            2+ "), std::string::npos) << bench.output;
  const CommandRun scene = radmesh("info 007");
  EXPECT_EQ(scene.exitCode, 2);
  EXPECT_NE(scene.output.find("007"), std::string::npos) << scene.output;
}

TEST(OptionValues, WholeNumbersInAnotherBaseAreRefused) {
  for (const std::string value : {"0x10", "0b11", "0o17", "00x1"}) {
    const CommandRun run = radmesh("solve furnace --max-iterations 1 --resolution " + value);
    EXPECT_EQ(run.exitCode, 2) << value << ": " << run.output;
    EXPECT_NE(run.output.find("radmesh: error: --resolution: " + value +
                              " is not a whole number in decimal digits: give it in decimal"),
              std::string::npos)
        << run.output;
  }
}

// A whole number too large for the option was "not a whole number"; it is out of range, and the
// range is said, for a list's item too, and in radmesh-view's words alike (cli/usage_failure.h).
TEST(OptionValues, AWholeNumberPastTheRangeIsOutOfRange) {
  const std::string range = " is out of range: a whole number here is from -2147483648 to 2147483647 (radmesh ";
  const std::pair<std::string, std::string> cases[] = {
      {"solve office --resolution 99999999999",
       "--resolution: 99999999999" + range + "solve --help says what --resolution takes)"},
      {"solve office --max-iterations=-2147483649",
       "--max-iterations: -2147483649" + range + "solve --help says what --max-iterations takes)"},
      {"bench solve office --resolutions 64,99999999999",
       "--resolutions: 99999999999" + range + "bench solve --help says what --resolutions takes)"}};
  for (const auto& [arguments, says] : cases) {
    const CommandRun run = radmesh(arguments);
    EXPECT_EQ(run.exitCode, 2) << arguments << ": " << run.output;
    EXPECT_EQ(run.output, "radmesh: error: " + says + "\n") << arguments;
  }
  const CommandRun notANumber = radmesh("solve office --resolution 12x");
  EXPECT_EQ(notANumber.exitCode, 2);
  EXPECT_NE(notANumber.output.find("--resolution: 12x is not a whole number"), std::string::npos) << notANumber.output;
}

// --cell-groups without --cells (or --plan, which finds the cells too) was ignored without a word.
TEST(OptionValues, CellGroupsWithoutCellsIsRefused) {
  CommandRun run = radmesh("info two-rooms --cell-groups join");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_EQ(run.output, "radmesh: error: --cell-groups requires --cells (or --plan): it shapes the cells they find; "
                        "add --cells, or leave --cell-groups out\n");
  run = radmesh("info two-rooms --cells --cell-groups join");
  EXPECT_EQ(run.exitCode, 0) << run.output;
  run = radmesh("info two-rooms --cell-groups join --plan " + tempPath("plan.png"));
  EXPECT_EQ(run.exitCode, 0) << run.output;
}

// bench accuracy --name a/b wrote its outputs into a folder a/; "." made files named "..csv".
TEST(OptionValues, ABenchNameThatIsNoFileNameIsRefused) {
  for (const char* name : {"a/b", ".", ".."}) {
    const CommandRun run = radmesh(std::string("bench accuracy furnace --quick --name ") + name);
    EXPECT_EQ(run.exitCode, 2) << name << ": " << run.output;
    EXPECT_NE(run.output.find("is not a file name: give a name without '/'"), std::string::npos) << run.output;
  }
}

// The warning said to stop on the unshot power, which was already the stop, when --max-iterations
// had cut the solve short.
TEST(OptionValues, AFarFromConvergedWarningNamesTheCapThatStoppedTheSolve) {
  CommandRun run = radmesh("solve furnace --resolution 16 --max-iterations 20 --quiet");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("far from converged (docs/accuracy.md); --max-iterations 20 stopped it: raise it, or "
                            "leave it out to stop on what is left (--until-unshot 0.01, the default)"),
            std::string::npos)
      << run.output;
  run = radmesh("solve two-rooms --cells auto --cell 0.75 --resolution 16 --max-iterations 10 --quiet");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("--max-iterations 10 stopped it"), std::string::npos) << run.output;
  run = radmesh("solve furnace --resolution 16 --until 0.5 --quiet");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("far from converged (docs/accuracy.md); stop on what is left instead: --until 1 "
                            "--until-unshot 0.01 (the default)"),
            std::string::npos)
      << run.output;
  EXPECT_EQ(run.output.find("--max-iterations"), std::string::npos) << run.output;
}

// /proc takes no new file. Each output was found unwritable only when written, after the solve,
// and exited 1; now before any work, exit 2, naming the option.
TEST(OptionValues, EveryOutputIsFoundUnwritableBeforeTheWork) {
  const std::pair<std::string, std::string> cases[] = {
      {"solve furnace --stats /proc/radmesh.json", "--stats '/proc/radmesh.json': cannot write there"},
      {"solve furnace --out /proc/radmesh.glb", "--out '/proc/radmesh.glb': cannot write there"},
      {"solve furnace --checkpoint /proc/radmesh.ckpt", "--checkpoint '/proc/radmesh.ckpt': cannot write there"},
      {"info furnace --plan /proc/radmesh.png", "--plan '/proc/radmesh.png': cannot write there"},
      {"bench solve furnace --json /proc/radmesh.json", "--json '/proc/radmesh.json': cannot write there"},
  };
  for (const auto& [arguments, message] : cases) {
    const CommandRun run = radmesh(arguments);
    EXPECT_EQ(run.exitCode, 2) << arguments << ": " << run.output;
    EXPECT_NE(run.output.find("radmesh: error: " + message), std::string::npos) << arguments << ": " << run.output;
    EXPECT_EQ(run.output.find("does not exist"), std::string::npos) << arguments << ": " << run.output;
    EXPECT_EQ(run.output.find("solved"), std::string::npos) << arguments << ": " << run.output;
  }
}

// bench cells solved the first scene in full before it found the second missing.
TEST(OptionValues, ABenchOfSeveralScenesReadsThemAllBeforeSolvingAny) {
  const std::string bench = "bench cells two-rooms --resolution 16 --cell 0.75 --max-iterations 20 --skip-whole";
  CommandRun run = radmesh(bench + " " + tempPath("nosuch.mgf"));
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("nosuch.mgf: no such file"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("cells, 1 thread"), std::string::npos) << run.output;
  // Each row cut short by --max-iterations carries its "+", the two-thread one too.
  run = radmesh(bench);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("cells, 1 thread "), std::string::npos) << run.output;
  const size_t two = run.output.find("cells, 2 threads ");
  ASSERT_NE(two, std::string::npos) << run.output;
  EXPECT_NE(run.output.substr(two, run.output.find('\n', two) - two).find("+ "), std::string::npos) << run.output;
}

// At site coordinates the bounds printed four digits: both corners of a room read (5e+05, 5e+06, 0).
TEST(OptionValues, InfoPrintsSiteCoordinatesToTheMillimetre) {
  const std::string site = tempPath("site.mgf");
  std::ofstream(site) << "xf -t 512345.678 5012345.678 0\ni " << test::dataPath("daylight/room_one_window.mgf").string()
                      << "\nxf\n";
  const CommandRun run = radmesh("info " + site + " --sky 10000");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("bounding box    (512345.678, 5012345.678, 0) .. ("), std::string::npos) << run.output;
  EXPECT_NE(radmesh("info office").output.find("bounding box    (-0.15, 0, 0) .. (7.2, 5.7, 2.7) m"), std::string::npos);
}

}  // namespace
}  // namespace radmesh
