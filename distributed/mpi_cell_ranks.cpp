#include "distributed/mpi_cell_ranks.h"

#include <climits>
#include <stdexcept>
#include <string>

#include "parallel/mpi/mpi_session.h"

namespace radmesh::distributed {

namespace {

constexpr int kPortalPowerTag = 14;

int mpiCount(std::size_t n) {
  if (n > static_cast<std::size_t>(INT_MAX))
    throw mpi::MpiError("rank " + std::to_string(mpi::worldRank()) + ": a message of " + std::to_string(n) +
                        " doubles is more than MPI's int count holds");
  return static_cast<int>(n);
}

}  // namespace

MpiCellRanks::MpiCellRanks(MPI_Comm comm) : comm_(comm) {
  mpi::check(MPI_Comm_rank(comm_, &rank_), "MPI_Comm_rank");
  mpi::check(MPI_Comm_size(comm_, &size_), "MPI_Comm_size");
}

void MpiCellRanks::shareCells(const std::vector<int>& owner, std::vector<std::vector<double>>& perCell) {
  // Each process's cells go in cell order; every process knows every cell's owner and length.
  std::vector<std::size_t> counts(size_, 0);
  for (std::size_t c = 0; c < perCell.size(); ++c) counts[owner[c]] += perCell[c].size();
  std::vector<int> recvCounts(size_), displacements(size_);
  std::size_t total = 0;
  for (int r = 0; r < size_; ++r) recvCounts[r] = mpiCount(counts[r]), displacements[r] = mpiCount(total), total += counts[r];
  std::vector<double> mine;
  for (std::size_t c = 0; c < perCell.size(); ++c)
    if (owner[c] == rank_) mine.insert(mine.end(), perCell[c].begin(), perCell[c].end());
  std::vector<double> all(total);
  mpi::check(MPI_Allgatherv(mine.data(), mpiCount(mine.size()), MPI_DOUBLE, all.data(), recvCounts.data(),
                            displacements.data(), MPI_DOUBLE, comm_),
             "MPI_Allgatherv");
  ++sent_.gathers;
  sent_.gatherBytes += static_cast<long long>(mine.size() * sizeof(double)) * (size_ - 1);
  std::vector<std::size_t> at(displacements.begin(), displacements.end());
  for (std::size_t c = 0; c < perCell.size(); ++c) {
    std::size_t& from = at[owner[c]];
    std::copy(all.begin() + from, all.begin() + from + perCell[c].size(), perCell[c].begin());
    from += perCell[c].size();
  }
}

std::vector<std::vector<double>> MpiCellRanks::exchange(const std::vector<std::vector<double>>& outgoing,
                                                         const std::vector<std::size_t>& incomingSizes) {
  std::vector<std::vector<double>> incoming(size_);
  std::vector<MPI_Request> requests;
  std::vector<int> sources;
  for (int r = 0; r < size_; ++r) {
    if (incomingSizes[r] == 0) continue;
    incoming[r].resize(incomingSizes[r]);
    requests.emplace_back();
    sources.push_back(r);
    mpi::check(MPI_Irecv(incoming[r].data(), mpiCount(incoming[r].size()), MPI_DOUBLE, r, kPortalPowerTag, comm_,
                         &requests.back()),
               "MPI_Irecv");
  }
  const std::size_t receives = requests.size();
  for (int r = 0; r < size_; ++r) {
    if (outgoing[r].empty()) continue;
    requests.emplace_back();
    mpi::check(MPI_Isend(outgoing[r].data(), mpiCount(outgoing[r].size()), MPI_DOUBLE, r, kPortalPowerTag, comm_,
                         &requests.back()),
               "MPI_Isend");
    ++sent_.messages;
    sent_.bytes += static_cast<long long>(outgoing[r].size() * sizeof(double));
  }
  std::vector<MPI_Status> statuses(requests.size());
  mpi::check(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), statuses.data()), "MPI_Waitall");
  for (std::size_t k = 0; k < receives; ++k) {  // a shorter message than the links call for
    int count = 0;
    mpi::check(MPI_Get_count(&statuses[k], MPI_DOUBLE, &count), "MPI_Get_count");
    if (static_cast<std::size_t>(count) != incomingSizes[sources[k]])
      throw mpi::MpiError("rank " + std::to_string(rank_) + ": rank " + std::to_string(sources[k]) + " sent " +
                          std::to_string(count) + " doubles of portal power, not the " +
                          std::to_string(incomingSizes[sources[k]]) + " its links to this rank's cells hold");
  }
  return incoming;
}

std::vector<CellTraffic> MpiCellRanks::traffic() {
  const long long mine[4] = {sent_.messages, sent_.bytes, sent_.gathers, sent_.gatherBytes};
  std::vector<long long> all(4 * static_cast<std::size_t>(size_));
  mpi::check(MPI_Allgather(mine, 4, MPI_LONG_LONG, all.data(), 4, MPI_LONG_LONG, comm_), "MPI_Allgather");
  std::vector<CellTraffic> out(size_);
  for (int r = 0; r < size_; ++r) out[r] = {all[4 * r], all[4 * r + 1], all[4 * r + 2], all[4 * r + 3]};
  return out;
}

}  // namespace radmesh::distributed
