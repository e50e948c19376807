#pragma once
// The mesh back end's machine split over the processes of a run (`--backend mesh --distributed`):
// one block of the PE torus each (emulator/mpi/mpi_transport.h), and what each process sent for
// the stats' "distributed". The solver sees only the emulator's Transport (SolveOptions::meshTransport).
#include <memory>
#include <string>
#include <vector>

namespace radmesh::emu {
class Transport;
}

namespace radmesh::distributed {

// The processes of MPI_COMM_WORLD as a periodic grid of ranks (collective).
std::shared_ptr<emu::Transport> meshProcesses();

struct ChannelTraffic {
  std::string channel;  // "xnet", "router", "reduce", "scan", "sort", "front end"
  long long messages = 0;
  long long bytes = 0;
};
struct MeshRankTraffic {
  int rank = 0;
  int rankRow = 0;
  int rankCol = 0;
  int pes = 0;  // of its block
  std::vector<ChannelTraffic> channels;
};

// Every process's PEs and what it has sent so far, by rank (collective).
std::vector<MeshRankTraffic> meshTraffic(const emu::Transport& processes, int peRows, int peCols);

}  // namespace radmesh::distributed
