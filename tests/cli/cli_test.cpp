// The `radmesh` command as a user runs it: exit codes, messages, and the JSON others depend on.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/test_paths.h"

namespace radmesh {
namespace {

struct CommandRun {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

CommandRun radmesh(const std::string& arguments) {
  const std::string command = (test::binaryDir() / "cli" / "radmesh").string() + " " + arguments + " 2>&1";
  CommandRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  std::array<char, 4096> buffer{};
  while (size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) run.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

std::string tempPath(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("radmesh-cli-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

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

TEST(Cli, ImpossibleOptionsAreRefusedNamingTheFlag) {
  CommandRun run = radmesh("solve furnace --resolution 8");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--resolution"), std::string::npos) << run.output;
  run = radmesh("info furnace --cell 0");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--cell"), std::string::npos) << run.output;
  run = radmesh("solve furnace --projection sphere");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("sphere"), std::string::npos) << run.output;
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

TEST(Cli, BenchAccuracyQuickWritesTableCsvAndJson) {
  const std::string dir = tempPath("accuracy");
  const CommandRun run = radmesh("bench accuracy furnace --quick --out-dir " + dir);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  std::ifstream in(dir + "/furnace.json");
  const auto j = nlohmann::json::parse(in);
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
    ASSERT_EQ(j["per_iteration"].size(), 5u);
    for (const auto& it : j["per_iteration"]) {
      for (const char* key : {"depth_a_max", "depth_b_max", "depth_a_hist", "depth_b_hist", "emulated_seconds", "op_counts"})
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
    const CommandRun run = radmesh(std::string("solve furnace --preset paper --quiet --until 0.5 --effects ") + mode + " --stats " + stats);
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

// Width and height from a PNG's IHDR chunk (big-endian, bytes 16..23).
std::pair<int, int> pngSize(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<unsigned char, 24> head{};
  in.read(reinterpret_cast<char*>(head.data()), head.size());
  if (!in || head[1] != 'P' || head[2] != 'N' || head[3] != 'G') return {-1, -1};
  auto be = [&](int at) { return (head[at] << 24) | (head[at + 1] << 16) | (head[at + 2] << 8) | head[at + 3]; };
  return {be(16), be(20)};
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
  const CommandRun read = radmesh("render " + bake + " --resolution 64 --preset paper --size 96x64 --out " + fromBake);
  ASSERT_EQ(read.exitCode, 0) << read.output;
  EXPECT_NE(read.output.find("read bake"), std::string::npos) << read.output;
  EXPECT_NE(read.output.find("warning: --resolution does not apply"), std::string::npos) << read.output;
  EXPECT_NE(read.output.find("warning: --preset does not apply"), std::string::npos) << read.output;
  EXPECT_EQ(read.output.find("--cell does not apply"), std::string::npos) << read.output;
  EXPECT_EQ(pngSize(fromBake), std::make_pair(96, 64));
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
      {"--camera 0.2,0.2,0.2 --look 0.2,0.2,0.2", "--camera/--look/--fov"},
  };
  for (const auto& [options, named] : cases) {
    const CommandRun run = radmesh("render cornell --cell 0.2 --iterations 1 " + options + " --out " + out);
    EXPECT_EQ(run.exitCode, 2) << options << ": " << run.output;
    EXPECT_NE(run.output.find(named), std::string::npos) << options << ": " << run.output;
  }
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace radmesh

namespace radmesh {
namespace {

// k shooters per iteration: half the iterations for k = 2, and the emulated MP-1 time only on the mesh.
TEST(Cli, BenchSolveTimesEveryShooterCountOnEitherBackEnd) {
  for (const std::string backend : {"native", "mesh"}) {
    const std::string json = tempPath("bench-" + backend + ".json");
    const CommandRun run = radmesh("bench solve cornell --cell 0.1 --backend " + backend +
                                   " --projections plane --resolutions 64 --shooters 1,2 --until 0.9 --json " + json);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    std::ifstream in(json);
    const auto j = nlohmann::json::parse(in);
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

// With no options, `solve` gives what docs/accuracy.md recommends for a bake: the hemicube at
// 256², until at most 1 % of the emitted power is unshot, and the unshot power at every iteration.
TEST(Cli, SolveByDefaultBakesToAtMostOnePercentUnshot) {
  const std::string stats = tempPath("stats.json");
  const CommandRun run = radmesh("solve office --quiet --stats " + stats);
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
  // Flags beside the preset win, before or after it.
  run = radmesh("solve cornell --cell 0.1 --quiet --until 0.5 --preset paper --resolution 64 --stats " + stats);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  j = nlohmann::json::parse(std::ifstream(stats));
  EXPECT_EQ(j["projection"], "plane");
  EXPECT_EQ(j["resolution"], 64);
  EXPECT_EQ(j["until"], 0.5);
  run = radmesh("solve cornell --preset fast");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.output.find("--preset 'fast' is unknown"), std::string::npos) << run.output;
}

// A path that would fail after a long solve is refused before it starts, naming the option and the fix.
TEST(Cli, OutputPathsAreCheckedBeforeTheSolve) {
  const std::string missing = tempPath("no-such-folder") + "/x";
  const std::map<std::string, std::string> cases = {
      {"solve office --out " + missing + ".glb", "--out '" + missing + ".glb': the folder"},
      {"solve office --out " + tempPath("x.png"), "give a path ending in .glb"},
      {"solve office --stats " + missing + ".json", "--stats '" + missing + ".json': the folder"},
      {"solve office --stats " + tempPath("x.txt"), "give a path ending in .json"},
      {"bench solve office --json " + missing + ".json", "--json '" + missing + ".json': the folder"},
  };
  for (const auto& [arguments, message] : cases) {
    const CommandRun run = radmesh(arguments);
    EXPECT_EQ(run.exitCode, 2) << arguments << ": " << run.output;
    EXPECT_NE(run.output.find(message), std::string::npos) << arguments << ": " << run.output;
    EXPECT_EQ(run.output.find("solving"), std::string::npos) << arguments << ": " << run.output;
  }
  EXPECT_NE(radmesh("solve office --out " + missing + ".glb").output.find("mkdir -p"), std::string::npos);
  if (radmesh("render --help").output.find("not built") != std::string::npos) return;
  for (const std::string& out : {missing + ".png", tempPath("x.jpg")}) {
    const CommandRun run = radmesh("render office --out " + out);
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("--out '" + out + "'"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("solved"), std::string::npos) << run.output;
  }
}

}  // namespace
}  // namespace radmesh
