// `radmesh solve --cells auto --distributed` and `--backend mesh --distributed` under mpirun, as a
// user runs them.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_run.h"

namespace radmesh {
namespace {

constexpr const char* kCellsSolve = "solve two-rooms --cells auto --cell 0.75 --resolution 32 --until-unshot 0.05 --quiet";
constexpr const char* kBench = "bench solve two-rooms --cells auto --cell 0.75 --projections hemicube --resolutions 32 "
                               "--until 1 --until-unshot 0.05 --threads 1";

constexpr const char* kMesh =
    "solve cornell --backend mesh --pe-grid 16x16 --resolution 32 --max-iterations 3 --shooters 2 --threads 1 --quiet";

TEST(DistributedCli, NeedsCellsAutoOrBackendMesh) {
  const CommandRun run = radmesh("solve two-rooms --distributed");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--distributed splits a solve over processes: give --cells auto (each process solves "
                            "some cells) or --backend mesh (each process holds a block of the PE machine)"),
            std::string::npos)
      << run.output;
  const CommandRun bench = radmesh("bench solve two-rooms --distributed");
  EXPECT_EQ(bench.exitCode, 2) << bench.output;
  EXPECT_NE(bench.output.find("bench solve --distributed measures a cells solve over processes: give --cells auto"),
            std::string::npos)
      << bench.output;
}

// One of several processes of an MPI launch (the environment mpirun sets, Open MPI's or MPICH's)
// without --distributed would run the whole command and write the same files: refused, said once.
TEST(DistributedCli, AnMpiLaunchWithoutDistributedIsRefused) {
  const std::string out = tempPath("raced.glb");
  for (const std::string launcher : {"OMPI_COMM_WORLD_SIZE=2 OMPI_COMM_WORLD_RANK=", "PMI_SIZE=3 PMI_RANK="})
    for (const char* rank : {"0", "1"}) {
      const CommandRun run = runCommand(launcher + rank + " " + (test::binaryDir() / "cli" / "radmesh").string() +
                                        " solve two-rooms --cells auto --resolution 16 --out " + out);
      EXPECT_EQ(run.exitCode, 2) << run.output;
      EXPECT_EQ(run.output.find("of an MPI launch, without --distributed") != std::string::npos, rank == std::string("0"))
          << run.output;
      EXPECT_FALSE(std::filesystem::exists(out));
    }
  const CommandRun one = runCommand("OMPI_COMM_WORLD_SIZE=1 " + (test::binaryDir() / "cli" / "radmesh").string() +
                                    " info cornell");
  EXPECT_EQ(one.exitCode, 0) << one.output;  // mpirun -np 1 is one process
}

// A usage error every process of a launch meets alike is said by rank 0 alone (sixteen ranks said
// it sixteen times); each exits 2.
TEST(DistributedCli, AUsageErrorIsSaidOnceAcrossALaunch) {
  const std::string radmeshPath = (test::binaryDir() / "cli" / "radmesh").string();
  for (const std::string bad : {"--portal-bins x", "--exchange-shots 0"})
    for (const char* rank : {"0", "1"}) {
      const CommandRun run = runCommand(std::string("OMPI_COMM_WORLD_SIZE=2 OMPI_COMM_WORLD_RANK=") + rank + " " +
                                        radmeshPath + " solve two-rooms --cells auto --distributed " + bad);
      EXPECT_EQ(run.exitCode, 2) << bad << ", rank " << rank << ": " << run.output;
      EXPECT_EQ(run.output.find("--") != std::string::npos, rank == std::string("0")) << bad << ", rank " << rank
                                                                                      << ": " << run.output;
    }
}

TEST(DistributedCli, BenchCsvNeedsDistributed) {
  const CommandRun run = radmesh(std::string(kBench) + " --csv " + tempPath("stem"));
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--csv writes the per-rank figures of a distributed run: give --distributed"),
            std::string::npos)
      << run.output;
}

#ifdef RADMESH_MPIEXEC
// Processes under mpirun (as root too, more ranks than cores), with `environment` (NAME=value).
CommandRun radmeshOnRanks(int ranks, const std::string& arguments, const std::string& environment = "") {
  const std::string name = environment.substr(0, environment.find('='));
  return runCommand(std::string("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
                                "OMPI_MCA_rmaps_base_oversubscribe=1 ") +
                    environment + " " + RADMESH_MPIEXEC + (name.empty() ? "" : " -x " + name) + " -np " +
                    std::to_string(ranks) + " " + (test::binaryDir() / "cli" / "radmesh").string() + " " + arguments);
}

std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The stats and the bake of two processes are the one process's, bit for bit, and only rank 0
// prints (one summary line).
TEST(DistributedCli, TwoRanksWriteTheOneProcessStatsAndBake) {
  const std::string alone = tempPath("alone.json"), split = tempPath("split.json");
  const std::string aloneBake = tempPath("alone.glb"), splitBake = tempPath("split.glb");
  const CommandRun one = radmesh(std::string(kCellsSolve) + " --stats " + alone + " --out " + aloneBake);
  ASSERT_EQ(one.exitCode, 0) << one.output;
  const CommandRun two = radmeshOnRanks(2, std::string(kCellsSolve) + " --distributed --stats " + split + " --out " + splitBake);
  ASSERT_EQ(two.exitCode, 0) << two.output;
  size_t summaries = 0;
  for (size_t at = two.output.find("solved: "); at != std::string::npos; at = two.output.find("solved: ", at + 1)) ++summaries;
  EXPECT_EQ(summaries, 1u) << two.output;

  nlohmann::json a = nlohmann::json::parse(fileBytes(alone)), b = nlohmann::json::parse(fileBytes(split));
  const nlohmann::json distributed = b["distributed"];
  for (const char* key : {"ledger", "per_cell", "iterations", "rounds", "cells", "portals", "unshot_fraction"})
    EXPECT_EQ(b[key], a[key]) << key;
  ASSERT_EQ(distributed["ranks"], 2);
  int shots = 0;
  for (const nlohmann::json& rank : distributed["per_rank"]) {
    shots += rank["shots"].get<int>();
    EXPECT_EQ(rank["messages"], b["rounds"]) << "one message a round to the one neighbour";
    // Less than the one portal's patches' 48 direction bins (4 x 4) of 3 doubles each every round:
    // only the lit bins go (their exact count: DistributedCells.* and the bench's test below).
    EXPECT_LT(rank["bytes"].get<long long>(),
              b["rounds"].get<int>() * b["per_cell"][0]["portal_patches"].get<int>() * 48 * 3 * 8);
    EXPECT_EQ(rank["bytes"].get<long long>() % 8, 0);
  }
  EXPECT_EQ(shots, a["iterations"]);
  EXPECT_EQ(fileBytes(splitBake), fileBytes(aloneBake));
}

// bench solve --distributed on 2 ranks: the one-process bench's shots and absorbed power, and each
// rank's figures: its cells' shots, one message a round to its one neighbour, its bytes what the
// model (from the same run) says its links sent, and only rank 0 prints the table.
TEST(DistributedCli, BenchSolveOnTwoRanksReportsEachRanksFigures) {
  const std::string alone = tempPath("bench-alone.json"), split = tempPath("bench-split.json");
  const std::string stem = tempPath("bench-split");
  const CommandRun one = radmesh(std::string(kBench) + " --json " + alone);
  ASSERT_EQ(one.exitCode, 0) << one.output;
  const CommandRun two = radmeshOnRanks(2, std::string(kBench) + " --distributed --json " + split + " --csv " + stem);
  ASSERT_EQ(two.exitCode, 0) << two.output;
  size_t tables = 0;
  for (size_t at = two.output.find("per rank (2 ranks"); at != std::string::npos;
       at = two.output.find("per rank (2 ranks", at + 1))
    ++tables;
  EXPECT_EQ(tables, 1u) << two.output;

  const nlohmann::json a = nlohmann::json::parse(fileBytes(alone))["rows"][0];
  const nlohmann::json b = nlohmann::json::parse(fileBytes(split))["rows"][0];
  EXPECT_EQ(b["iterations_to_until"], a["iterations_to_until"]);
  EXPECT_EQ(b["absorbed_w"].get<double>(), a["absorbed_w"].get<double>());  // bit for bit
  EXPECT_EQ(b["rounds"], a["rounds"]);
  const int rounds = b["rounds"].get<int>();
  const nlohmann::json& ranks = b["distributed"]["per_rank"];
  ASSERT_EQ(ranks.size(), 2u);
  int shots = 0, cells = 0;
  double maxBytesPerRound = 0.0, allBytes = 0.0;
  for (const nlohmann::json& rank : ranks) {
    shots += rank["shots"].get<int>();
    cells += rank["cells"].get<int>();
    EXPECT_EQ(rank["cells"], 1) << "two rooms, one each";
    EXPECT_EQ(rank["messages"], rounds) << "one message a round to the one neighbour";
    EXPECT_EQ(rank["gathers"], 2 * rounds + 1) << "made, then twice a round";
    EXPECT_GT(rank["wall_seconds"].get<double>(), 0.0);
    EXPECT_LE(rank["mpi_wait_seconds"].get<double>(), rank["wall_seconds"].get<double>());
    maxBytesPerRound = std::max(maxBytesPerRound, rank["bytes_per_round"].get<double>());
    allBytes += rank["bytes"].get<double>();
  }
  EXPECT_EQ(shots, a["iterations_to_until"]);
  EXPECT_EQ(cells, 2);
  const nlohmann::json& model = b["distributed"]["model"];
  ASSERT_EQ(model[1]["ranks"], 2);
  EXPECT_EQ(model[1]["max_messages_per_round"], 1);
  EXPECT_EQ(model[1]["max_bytes_per_round"].get<double>(), maxBytesPerRound) << "the model's 2 ranks are the run's";
  EXPECT_DOUBLE_EQ(model[1]["all_bytes_per_round"].get<double>(), allBytes / rounds);
  EXPECT_EQ(model[0]["all_bytes_per_round"], 0.0);
  // The CSV: a row per rank, a row per model point.
  const std::string ranksCsv = fileBytes(stem + "-ranks.csv"), modelCsv = fileBytes(stem + "-model.csv");
  EXPECT_EQ(std::count(ranksCsv.begin(), ranksCsv.end(), '\n'), 3);
  EXPECT_EQ(std::count(modelCsv.begin(), modelCsv.end(), '\n'), 10);
}

// The stats without what differs from run to run: wall and host seconds, and the split itself.
nlohmann::json withoutTimes(nlohmann::json j) {
  if (j.is_object()) {
    for (const char* key : {"seconds", "host_seconds", "distributed"}) j.erase(key);
    for (auto& [key, value] : j.items()) value = withoutTimes(value);
  } else if (j.is_array()) {
    for (auto& value : j) value = withoutTimes(value);
  }
  return j;
}

// The mesh machine over two processes: the stats (shooters, ledger, depths, cost counts per
// iteration) and the bake are one process's, bit for bit; the "distributed" section gives each
// process its block of the 256 PEs and what it sent, which the router and the gathers make non-zero.
TEST(DistributedCli, MeshOnTwoRanksWritesTheOneProcessStatsAndBake) {
  const std::string alone = tempPath("mesh-alone.json"), split = tempPath("mesh-split.json");
  const std::string aloneBake = tempPath("mesh-alone.glb"), splitBake = tempPath("mesh-split.glb");
  const CommandRun one = radmesh(std::string(kMesh) + " --stats " + alone + " --out " + aloneBake);
  ASSERT_EQ(one.exitCode, 0) << one.output;
  const CommandRun two = radmeshOnRanks(2, std::string(kMesh) + " --distributed --stats " + split + " --out " + splitBake);
  ASSERT_EQ(two.exitCode, 0) << two.output;
  EXPECT_EQ(two.output.find("solved: "), two.output.rfind("solved: ")) << "rank 0 alone prints\n" << two.output;

  const nlohmann::json a = nlohmann::json::parse(fileBytes(alone)), b = nlohmann::json::parse(fileBytes(split));
  ASSERT_EQ(a["iterations"], 3);
  EXPECT_EQ(withoutTimes(b), withoutTimes(a));
  const nlohmann::json& distributed = b["distributed"];
  ASSERT_EQ(distributed["ranks"], 2) << distributed.dump();
  for (const nlohmann::json& rank : distributed["per_rank"]) {
    EXPECT_EQ(rank["pes"], 128);
    EXPECT_GT(rank["channels"]["router"]["messages"].get<long long>(), 0);
    EXPECT_GT(rank["channels"]["front end"]["bytes"].get<long long>(), 0);
    EXPECT_EQ(rank["messages_per_iteration"].get<double>(), rank["messages"].get<double>() / 3);
  }
  EXPECT_EQ(fileBytes(splitBake), fileBytes(aloneBake));
}

// The mesh machine over two processes stopped after one iteration with a checkpoint (rank 0 writes
// it) and resumed over two: the one-process solve's bake, byte for byte.
TEST(DistributedCli, AMeshCheckpointOfTwoRanksResumesToTheOneProcessBake) {
  const std::string alone = tempPath("mesh-ckpt-alone.glb"), resumed = tempPath("mesh-ckpt-resumed.glb");
  const std::string checkpoint = tempPath("mesh.ckpt");
  std::string first = kMesh;
  first.replace(first.find("--max-iterations 3"), 18, "--max-iterations 1");
  ASSERT_EQ(radmesh(std::string(kMesh) + " --out " + alone).exitCode, 0);
  CommandRun run = radmeshOnRanks(2, first + " --distributed --checkpoint " + checkpoint);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  run = radmeshOnRanks(2, std::string(kMesh) + " --distributed --resume " + checkpoint + " --out " + resumed);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("resumed from " + checkpoint + " after iteration 1"), std::string::npos) << run.output;
  EXPECT_EQ(fileBytes(resumed), fileBytes(alone));
}

// Rank 0 cannot write its stats (the disk is full: /dev/full) while rank 1 waits for it in the
// bake's gather: the run ends, non-zero, with the rank in the message.
TEST(DistributedCli, AnErrorOnOneRankEndsTheRunNamingTheRank) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full to fill";
  const std::string full = tempPath("stats.json");
  std::filesystem::create_symlink("/dev/full", full);
  const CommandRun run =
      radmeshOnRanks(2, std::string(kCellsSolve) + " --distributed --stats " + full + " --out " + tempPath("out.glb"));
  EXPECT_NE(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("radmesh: rank 0: error: " + full + ": write failed (disk full?)"), std::string::npos)
      << run.output;
}
// The stats but the wall time, where it was resumed and the run's own traffic (a resumed run sends
// only its rounds').
nlohmann::json withoutTimeAndTraffic(nlohmann::json stats) {
  stats.erase("seconds");
  stats.erase("resumed_after_iterations");
  stats.erase("distributed");
  return stats;
}

// A straight one-process run's stats and bake: what every resumed run below must give.
struct Straight {
  nlohmann::json stats;
  std::string bake;
};
Straight straightRun() {
  const std::string stats = tempPath("straight.json"), bake = tempPath("straight.glb");
  const CommandRun run = radmesh(std::string(kCellsSolve) + " --stats " + stats + " --out " + bake);
  EXPECT_EQ(run.exitCode, 0) << run.output;
  return {withoutTimeAndTraffic(nlohmann::json::parse(fileBytes(stats))), fileBytes(bake)};
}

// `run` (a resume writing `stats` and `bake`) gave the straight run's, bit for bit.
void expectTheStraightRun(const CommandRun& run, const Straight& straight, const std::string& stats,
                          const std::string& bake) {
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(withoutTimeAndTraffic(nlohmann::json::parse(fileBytes(stats))).dump(), straight.stats.dump());
  EXPECT_TRUE(fileBytes(bake) == straight.bake) << "the resumed bake differs from the straight one";
}

// Rank 0 gathers both processes' cells into one checkpoint, which resumes on two processes or on
// one to the one process's stats and bake.
TEST(DistributedCli, ACheckpointOfTwoRanksResumesOnTwoOrOne) {
  const Straight straight = straightRun();
  const std::string checkpoint = tempPath("two.ckpt"), stats = tempPath("resumed.json"), bake = tempPath("resumed.glb");
  CommandRun run = radmeshOnRanks(2, std::string(kCellsSolve) + " --distributed --max-iterations 60 --checkpoint " + checkpoint);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("wrote checkpoint " + checkpoint), std::string::npos) << run.output;
  run = radmeshOnRanks(2, std::string(kCellsSolve) + " --distributed --resume " + checkpoint + " --stats " + stats +
                              " --out " + bake);
  EXPECT_NE(run.output.find("resumed from " + checkpoint + " after round "), std::string::npos) << run.output;
  expectTheStraightRun(run, straight, stats, bake);
  run = radmesh(std::string(kCellsSolve) + " --resume " + checkpoint + " --stats " + stats + " --out " + bake);
  expectTheStraightRun(run, straight, stats, bake);
}

// A process that dies (SIGKILL) or whose message fails in round 3 stops the run, non-zero,
// naming the rank, before any output; the checkpoint of round 2 resumes to the straight run.
TEST(DistributedCli, ARankThatDiesOrAFailedMessageStopsTheRunAndItResumes) {
  const Straight straight = straightRun();
  for (const std::string how : {"kill", "fail"}) {
    const std::string checkpoint = tempPath(how + ".ckpt"), stats = tempPath(how + ".json");
    const std::string bake = tempPath(how + ".glb");
    CommandRun run = radmeshOnRanks(2, std::string(kCellsSolve) + " --distributed --checkpoint " + checkpoint +
                                           " --checkpoint-every 0.000001 --out " + bake,
                                    "RADMESH_TEST_FAULT=1:3:" + how);
    EXPECT_NE(run.exitCode, 0) << run.output;
    const std::string names = how == "kill" ? "process rank 1" : "radmesh: rank 1: error: MPI_Isend failed";
    EXPECT_NE(run.output.find(names), std::string::npos) << run.output;
    EXPECT_FALSE(std::filesystem::exists(bake));
    run = radmeshOnRanks(2, std::string(kCellsSolve) + " --distributed --resume " + checkpoint + " --stats " + stats +
                                " --out " + bake);
    EXPECT_NE(run.output.find("after round 2 "), std::string::npos) << run.output;
    expectTheStraightRun(run, straight, stats, bake);
  }
}
#else
TEST(DistributedCli, RefusedWithoutMpi) {
  for (const char* command : {kCellsSolve, kBench}) {
    const CommandRun run = radmesh(std::string(command) + " --distributed");
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("built without MPI"), std::string::npos) << run.output;
  }
}
#endif

}  // namespace
}  // namespace radmesh
