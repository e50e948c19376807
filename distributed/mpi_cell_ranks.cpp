#include "distributed/mpi_cell_ranks.h"

#include <climits>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

#include "parallel/mpi/mpi_session.h"

namespace radmesh::distributed {

namespace {

constexpr int kPortalPowerTag = 14;

int mpiCount(std::size_t n) {
  if (n > static_cast<std::size_t>(INT_MAX))
    throw mpi::MpiError("rank " + std::to_string(mpi::worldRank()) + ": a message of " + std::to_string(n) +
                        " elements is more than MPI's int count holds");
  return static_cast<int>(n);
}

}  // namespace

MpiCellRanks::MpiCellRanks(MPI_Comm comm) : comm_(comm) {
  mpi::check(MPI_Comm_rank(comm_, &rank_), "MPI_Comm_rank");
  mpi::check(MPI_Comm_size(comm_, &size_), "MPI_Comm_size");
  if (const char* fault = std::getenv("RADMESH_TEST_FAULT")) {
    int rank = -1;
    long long exchange = 0;
    char how[8] = {};
    if (std::sscanf(fault, "%d:%lld:%7s", &rank, &exchange, how) != 3 || exchange < 1 ||
        (std::strcmp(how, "kill") != 0 && std::strcmp(how, "fail") != 0))
      throw std::invalid_argument(std::string("RADMESH_TEST_FAULT=") + fault + " is not RANK:EXCHANGE:kill or fail");
    if (rank == rank_) faultExchange_ = exchange, faultKills_ = std::strcmp(how, "kill") == 0;
  }
}

// A process that dies, or a message that fails, on purpose: what a run must survive with
// --checkpoint (docs/cells.md).
void MpiCellRanks::injectFault() {
  if (++exchanges_ != faultExchange_) return;
  if (faultKills_) std::raise(SIGKILL);
  throw mpi::MpiError("rank " + std::to_string(rank_) + ": MPI_Isend failed: RADMESH_TEST_FAULT at exchange " +
                      std::to_string(exchanges_));
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
  injectFault();
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

std::vector<std::string> MpiCellRanks::gatherOnFirst(const std::string& bytes) {
  const unsigned long long size = bytes.size();
  std::vector<unsigned long long> sizes(size_);
  mpi::check(MPI_Gather(&size, 1, MPI_UNSIGNED_LONG_LONG, sizes.data(), 1, MPI_UNSIGNED_LONG_LONG, 0, comm_),
             "MPI_Gather");
  std::vector<int> counts(size_), displacements(size_);
  std::size_t total = 0;
  if (rank_ == 0)
    for (int r = 0; r < size_; ++r) counts[r] = mpiCount(sizes[r]), displacements[r] = mpiCount(total), total += sizes[r];
  std::string all(total, '\0');
  mpi::check(MPI_Gatherv(bytes.data(), mpiCount(bytes.size()), MPI_CHAR, all.data(), counts.data(),
                         displacements.data(), MPI_CHAR, 0, comm_),
             "MPI_Gatherv");
  std::vector<std::string> byRank;
  if (rank_ == 0)
    for (int r = 0; r < size_; ++r) byRank.push_back(all.substr(displacements[r], sizes[r]));
  return byRank;
}

bool MpiCellRanks::firstSays(bool flag) {
  int value = flag ? 1 : 0;
  mpi::check(MPI_Bcast(&value, 1, MPI_INT, 0, comm_), "MPI_Bcast");
  return value != 0;
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
