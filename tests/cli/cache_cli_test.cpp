// The form-factor cache as `radmesh solve` sets it unless told: on the native back end every
// patch that shoots again is served from the cache, and the answer is bitwise the uncached one.
#include <gtest/gtest.h>

#include <string>

#include "tests/cli/cli_run.h"

namespace radmesh {
namespace {

TEST(CliCache, TheHostCachesEveryRowShotAgainByDefaultAndTheAnswerIsTheUncachedOne) {
  const std::string solve = "solve cornell --cell 0.2 --resolution 64 --threads 1 ";
  const std::string cachedStats = tempPath("cached.json"), cachedBake = tempPath("cached.glb");
  const CommandRun cached = radmesh(solve + "--stats " + cachedStats + " --out " + cachedBake);
  ASSERT_EQ(cached.exitCode, 0) << cached.output;
  const std::string plainStats = tempPath("plain.json"), plainBake = tempPath("plain.glb");
  const CommandRun plain = radmesh(solve + "--cache-mb 0 --stats " + plainStats + " --out " + plainBake);
  ASSERT_EQ(plain.exitCode, 0) << plain.output;

  const nlohmann::json c = readJson(cachedStats), p = readJson(plainStats);
  EXPECT_GT(c["cache_mb"].get<double>(), 0.0);
  EXPECT_LE(c["cache_mb"].get<double>(), 1024.0);
  EXPECT_EQ(p["cache_mb"].get<double>(), 0.0);
  ASSERT_EQ(c["iterations"], p["iterations"]);
  int hits = 0, reused = 0;
  for (size_t i = 0; i < c["per_iteration"].size(); ++i) {
    const nlohmann::json& r = c["per_iteration"][i];
    EXPECT_EQ(r["cache_hits"], r["reused_rows"]) << "iteration " << i + 1;  // the budget holds every row
    EXPECT_EQ(p["per_iteration"][i]["cache_hits"], 0);
    hits += r["cache_hits"].get<int>();
    reused += r["reused_rows"].get<int>();
  }
  EXPECT_EQ(hits, reused);
  EXPECT_EQ(hits, 124);  // of 196 shots: 75 patches, most shooting more than once
  EXPECT_NE(cached.output.find("form-factor cache: 124 of 196 shots served without projecting"), std::string::npos)
      << cached.output;
  EXPECT_EQ(c["ledger"], p["ledger"]);
  EXPECT_EQ(readBytes(cachedBake), readBytes(plainBake));  // bitwise the same bake
}

// After --resume the cache line counts this run's shots, not the checkpoint's: the cache starts
// empty, so the resumed run's hits are the per-iteration cache_hits after the checkpoint. A resume
// that shoots nothing prints no cache line.
TEST(CliCache, AResumedSolveCountsOnlyItsOwnShots) {
  const std::string solve = "solve cornell --cell 0.2 --resolution 64 --threads 1 --quiet ";
  const std::string checkpoint = tempPath("first.ckpt"), stats = tempPath("resumed.json");
  ASSERT_EQ(radmesh(solve + "--max-iterations 120 --checkpoint " + checkpoint).exitCode, 0);
  CommandRun run = radmesh(solve + "--resume " + checkpoint + " --stats " + stats);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const nlohmann::json j = readJson(stats);
  ASSERT_EQ(j["iterations"], 196);  // as the straight solve above
  int hits = 0;
  for (size_t i = 120; i < j["per_iteration"].size(); ++i) hits += j["per_iteration"][i]["cache_hits"].get<int>();
  EXPECT_GT(hits, 0);
  EXPECT_NE(run.output.find("form-factor cache: " + std::to_string(hits) + " of this run's 76 shots served without projecting"),
            std::string::npos) << run.output;
  run = radmesh(solve + "--max-iterations 100 --resume " + checkpoint);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(run.output.find("form-factor cache"), std::string::npos) << run.output;
}

// The mesh back end's rows are its PEs' to hold, and there a row computed beside other shooters
// differs in its last bits: it caches only when told.
TEST(CliCache, TheMeshBackEndCachesOnlyWhenTold) {
  const std::string stats = tempPath("mesh.json");
  const std::string solve = "solve cornell --backend mesh --pe-grid 16x16 --cell 0.2 --resolution 64 --max-iterations 3 --stats " + stats;
  const CommandRun run = radmesh(solve);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(readJson(stats)["cache_mb"].get<double>(), 0.0);
  const CommandRun told = radmesh(solve + " --cache-mb 64");
  ASSERT_EQ(told.exitCode, 0) << told.output;
  EXPECT_EQ(readJson(stats)["cache_mb"].get<double>(), 64.0);
}

// The benches time uncached solves, so that a setting's time is its own shots, unless told; told,
// they time what `radmesh solve` runs, with the same answer.
TEST(CliCache, TheBenchesCacheOnlyWhenTold) {
  const std::string bench = "solve cornell --cell 0.2 --projections hemicube --resolutions 64 --until 1 "
                            "--until-unshot 0.01 --threads 1";
  const BenchRun plain = runBench(bench);
  const BenchRun cached = runBench(bench + " --cache-mb 64");
  EXPECT_EQ(plain.json["cache_mb"].get<double>(), 0.0);
  EXPECT_EQ(cached.json["cache_mb"].get<double>(), 64.0);
  EXPECT_NE(plain.output.find("no form-factor cache (--cache-mb)"), std::string::npos) << plain.output;
  EXPECT_NE(cached.output.find("a 64 MiB form-factor cache"), std::string::npos) << cached.output;
  const nlohmann::json& p = plain.json["rows"][0];
  const nlohmann::json& c = cached.json["rows"][0];
  EXPECT_EQ(p["cache_hits"], 0);
  EXPECT_EQ(c["cache_hits"], 124);  // as `radmesh solve` of the same mesh counts
  EXPECT_EQ(c["iterations_to_until"], p["iterations_to_until"]);
  EXPECT_EQ(c["absorbed_w"], p["absorbed_w"]);  // bitwise

  const BenchRun cells = runBench("cells two-rooms --cell 0.75 --resolution 16 --until-unshot 0.1 --skip-whole "
                                  "--cache-mb 8");
  EXPECT_EQ(cells.json["cache_mb"].get<double>(), 8.0);
  const CommandRun refused = radmesh("bench accuracy cornell --quick --cache-mb -1");
  EXPECT_NE(refused.exitCode, 0);
  EXPECT_NE(refused.output.find("--cache-mb must be a size in MiB"), std::string::npos) << refused.output;
}

}  // namespace
}  // namespace radmesh
