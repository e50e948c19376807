// `radmesh solve --cells auto --distributed` and `--backend mesh --distributed` under mpirun, as a
// user runs them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_run.h"

namespace radmesh {
namespace {

constexpr const char* kCells = "solve two-rooms --cells auto --cell 0.75 --resolution 32 --until-unshot 0.05 --quiet";

constexpr const char* kMesh =
    "solve cornell --backend mesh --pe-grid 16x16 --resolution 32 --max-iterations 3 --shooters 2 --threads 1 --quiet";

TEST(DistributedCli, NeedsCellsAutoOrBackendMesh) {
  const CommandRun run = radmesh("solve two-rooms --distributed");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--distributed splits a solve over processes: give --cells auto (each process solves "
                            "some cells) or --backend mesh (each process holds a block of the PE machine)"),
            std::string::npos)
      << run.output;
}

#ifdef RADMESH_MPIEXEC
// Two processes under mpirun (as root too, more ranks than cores).
CommandRun radmeshOnRanks(int ranks, const std::string& arguments) {
  return runCommand(std::string("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
                                "OMPI_MCA_rmaps_base_oversubscribe=1 ") +
                    RADMESH_MPIEXEC + " -np " + std::to_string(ranks) + " " +
                    (test::binaryDir() / "cli" / "radmesh").string() + " " + arguments);
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
  const CommandRun one = radmesh(std::string(kCells) + " --stats " + alone + " --out " + aloneBake);
  ASSERT_EQ(one.exitCode, 0) << one.output;
  const CommandRun two = radmeshOnRanks(2, std::string(kCells) + " --distributed --stats " + split + " --out " + splitBake);
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
    // The one portal's patches, 48 direction bins (4 x 4) of 3 doubles each.
    EXPECT_EQ(rank["bytes"], b["rounds"].get<int>() * b["per_cell"][0]["portal_patches"].get<int>() * 48 * 3 * 8);
  }
  EXPECT_EQ(shots, a["iterations"]);
  EXPECT_EQ(fileBytes(splitBake), fileBytes(aloneBake));
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

// Rank 0 cannot write its stats (the path is a folder) while rank 1 waits for it in the bake's
// gather: the run ends, non-zero, with the rank in the message.
TEST(DistributedCli, AnErrorOnOneRankEndsTheRunNamingTheRank) {
  const std::string folder = tempPath("stats.json");
  std::filesystem::create_directories(folder);
  const CommandRun run =
      radmeshOnRanks(2, std::string(kCells) + " --distributed --stats " + folder + " --out " + tempPath("out.glb"));
  EXPECT_NE(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("radmesh: rank 0: error: " + folder + ": cannot open for writing"), std::string::npos)
      << run.output;
}
#else
TEST(DistributedCli, RefusedWithoutMpi) {
  const CommandRun run = radmesh(std::string(kCells) + " --distributed");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("built without MPI"), std::string::npos) << run.output;
}
#endif

}  // namespace
}  // namespace radmesh
