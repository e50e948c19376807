#include "distributed/mesh_processes.h"

#include <mpi.h>

#include "emulator/mpi/mpi_transport.h"
#include "parallel/mpi/mpi_session.h"

namespace radmesh::distributed {

std::shared_ptr<emu::Transport> meshProcesses() { return std::make_shared<emu::MpiTransport>(); }

std::vector<MeshRankTraffic> meshTraffic(const emu::Transport& processes, int peRows, int peCols) {
  // Per rank: rank row, rank col, then messages and bytes per channel.
  std::vector<long long> mine = {processes.rankRow(), processes.rankCol()};
  for (int c = 0; c < emu::kChannels; ++c) {
    const emu::Traffic& t = processes.traffic(static_cast<emu::Channel>(c));
    mine.push_back(t.messages);
    mine.push_back(t.bytes);
  }
  const int ranks = processes.rankGrid().size();
  std::vector<long long> all(mine.size() * ranks);
  mpi::check(MPI_Allgather(mine.data(), static_cast<int>(mine.size()), MPI_LONG_LONG, all.data(),
                           static_cast<int>(mine.size()), MPI_LONG_LONG, MPI_COMM_WORLD),
             "MPI_Allgather");
  std::vector<MeshRankTraffic> out;
  for (int r = 0; r < ranks; ++r) {
    const long long* at = all.data() + r * mine.size();
    MeshRankTraffic t{r, static_cast<int>(at[0]), static_cast<int>(at[1]), peRows * peCols / ranks, {}};
    for (int c = 0; c < emu::kChannels; ++c)
      t.channels.push_back({emu::toString(static_cast<emu::Channel>(c)), at[2 + 2 * c], at[3 + 2 * c]});
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace radmesh::distributed
