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
  const double start = MPI_Wtime();
  mpi::check(MPI_Allgatherv(mine.data(), mpiCount(mine.size()), MPI_DOUBLE, all.data(), recvCounts.data(),
                            displacements.data(), MPI_DOUBLE, comm_),
             "MPI_Allgatherv");
  sent_.waitSeconds += MPI_Wtime() - start;
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
                                                         const std::vector<std::size_t>& incomingLimits) {
  const double start = MPI_Wtime();
  injectFault();
  std::vector<std::vector<double>> incoming(size_);
  std::vector<MPI_Request> requests;
  std::vector<int> sources;
  for (int r = 0; r < size_; ++r) {
    if (incomingLimits[r] == 0) continue;
    incoming[r].resize(incomingLimits[r]);
    requests.emplace_back();
    sources.push_back(r);
    mpi::check(MPI_Irecv(incoming[r].data(), mpiCount(incoming[r].size()), MPI_DOUBLE, r, kPortalPowerTag, comm_,
                         &requests.back()),
               "MPI_Irecv");
  }
  const std::size_t receives = requests.size();
  for (int r : sources) {  // neighbours are mutual: a message to each, empty when its portals are dark
    requests.emplace_back();
    mpi::check(MPI_Isend(outgoing[r].data(), mpiCount(outgoing[r].size()), MPI_DOUBLE, r, kPortalPowerTag, comm_,
                         &requests.back()),
               "MPI_Isend");
    ++sent_.messages;
    sent_.bytes += static_cast<long long>(outgoing[r].size() * sizeof(double));
  }
  std::vector<MPI_Status> statuses(requests.size());
  const int waited = MPI_Waitall(static_cast<int>(requests.size()), requests.data(), statuses.data());
  for (std::size_t k = 0; waited == MPI_ERR_IN_STATUS && k < receives; ++k)
    if (statuses[k].MPI_ERROR == MPI_ERR_TRUNCATE)
      throw mpi::MpiError("rank " + std::to_string(rank_) + ": rank " + std::to_string(sources[k]) +
                          " sent more portal power than its links to this rank's cells can hold");
  mpi::check(waited, "MPI_Waitall");
  for (std::size_t k = 0; k < receives; ++k) {  // what came: at most the limit
    int count = 0;
    mpi::check(MPI_Get_count(&statuses[k], MPI_DOUBLE, &count), "MPI_Get_count");
    incoming[sources[k]].resize(static_cast<std::size_t>(count));
  }
  sent_.waitSeconds += MPI_Wtime() - start;
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
  // Counts as doubles: exact below 2^53.
  const double mine[5] = {static_cast<double>(sent_.messages), static_cast<double>(sent_.bytes),
                          static_cast<double>(sent_.gathers), static_cast<double>(sent_.gatherBytes), sent_.waitSeconds};
  std::vector<double> all(5 * static_cast<std::size_t>(size_));
  mpi::check(MPI_Allgather(mine, 5, MPI_DOUBLE, all.data(), 5, MPI_DOUBLE, comm_), "MPI_Allgather");
  std::vector<CellTraffic> out(size_);
  for (int r = 0; r < size_; ++r) {
    const double* a = &all[5 * static_cast<std::size_t>(r)];
    out[r] = {static_cast<long long>(a[0]), static_cast<long long>(a[1]), static_cast<long long>(a[2]),
              static_cast<long long>(a[3]), a[4]};
  }
  return out;
}

std::vector<double> MpiCellRanks::allGather(double value) {
  std::vector<double> all(static_cast<std::size_t>(size_));
  mpi::check(MPI_Allgather(&value, 1, MPI_DOUBLE, all.data(), 1, MPI_DOUBLE, comm_), "MPI_Allgather");
  return all;
}

}  // namespace radmesh::distributed
