#include "cli/distributed_command.h"

#include <algorithm>
#include <cstdlib>
#include <utility>

#include "solver/radiosity/progressive_solver.h"
#include "solver/scene/scene_error.h"
#ifdef RADMESH_HAVE_MPI
#include "distributed/distributed_run.h"
#include "distributed/mesh_processes.h"
#endif

namespace radmesh::cli {
namespace {

#ifdef RADMESH_HAVE_MPI
// The stats' "distributed" of a mesh solve over the processes: per rank its block of PEs and what
// it sent, in all and per iteration, by channel (docs/scaling.md).
nlohmann::json meshDistributedStats(const emu::Transport& processes, const ProgressiveSolver& solver) {
  const SolveOptions& o = solver.options();
  const double iterations = std::max<double>(static_cast<double>(solver.history().size()), 1.0);
  nlohmann::json perRank = nlohmann::json::array();
  for (const distributed::MeshRankTraffic& r : distributed::meshTraffic(processes, o.machine.rows, o.machine.cols)) {
    long long messages = 0, bytes = 0;
    nlohmann::json channels = nlohmann::json::object();
    for (const distributed::ChannelTraffic& c : r.channels) {
      channels[c.channel] = {{"messages", c.messages}, {"bytes", c.bytes}};
      messages += c.messages, bytes += c.bytes;
    }
    perRank.push_back({{"rank", r.rank},
                       {"rank_row", r.rankRow},
                       {"rank_col", r.rankCol},
                       {"pes", r.pes},
                       {"messages", messages},
                       {"bytes", bytes},
                       {"messages_per_iteration", messages / iterations},
                       {"bytes_per_iteration", bytes / iterations},
                       {"channels", std::move(channels)}});
  }
  return {{"ranks", perRank.size()}, {"split", "mesh machine"}, {"per_rank", std::move(perRank)}};
}
#endif

}  // namespace

Launch mpiLaunch() {
  auto number = [](const char* name) {
    const char* value = std::getenv(name);
    return value ? std::atoi(value) : -1;
  };
  for (const auto& [size, rank] : {std::pair{"OMPI_COMM_WORLD_SIZE", "OMPI_COMM_WORLD_RANK"},
                                   std::pair{"PMI_SIZE", "PMI_RANK"}})
    if (number(size) > 0) return {number(size), std::max(number(rank), 0)};
  return {};
}

void runDistributed(bool cellsOn, bool meshBackend, const std::function<void(Processes&)>& body) {
  if (!cellsOn && !meshBackend)
    throw OptionError("--distributed splits a solve over processes: give --cells auto (each process solves some "
                      "cells) or --backend mesh (each process holds a block of the PE machine)");
#ifdef RADMESH_HAVE_MPI
  distributed::runDistributed([&](CellRanks& ranks) {
    Processes processes{ranks, nullptr, nullptr};
    if (!cellsOn) {
      processes.meshMachine = distributed::meshProcesses();
      processes.meshStats = [&](const ProgressiveSolver& solver) {
        return meshDistributedStats(*processes.meshMachine, solver);
      };
    }
    body(processes);
  });
#else
  throw OptionError("--distributed: this radmesh was built without MPI; install libopenmpi-dev and openmpi-bin "
                    "(scripts/install-deps.sh), build again, and run it under mpirun");
#endif
}

}  // namespace radmesh::cli
