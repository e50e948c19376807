#pragma once
// CellRanks over MPI: every cell's figures by MPI_Allgatherv, portal power by MPI_Isend /
// MPI_Irecv between the processes whose cells share a portal, and nothing else. Counts what it
// sends and the wall time in those calls (docs/scaling.md, the stats' "distributed").
#include <mpi.h>

#include "solver/radiosity/cell_ranks.h"

namespace radmesh::distributed {

class MpiCellRanks : public CellRanks {
 public:
  explicit MpiCellRanks(MPI_Comm comm = MPI_COMM_WORLD);

  int rank() const override { return rank_; }
  int size() const override { return size_; }
  void shareCells(const std::vector<int>& owner, std::vector<std::vector<double>>& perCell) override;
  std::vector<std::vector<double>> exchange(const std::vector<std::vector<double>>& outgoing,
                                            const std::vector<std::size_t>& incomingLimits) override;
  std::vector<std::string> gatherOnFirst(const std::string& bytes) override;
  bool firstSays(bool flag) override;
  std::vector<CellTraffic> traffic() override;
  std::vector<double> allGather(double value) override;

 private:
  void injectFault();

  MPI_Comm comm_;
  int rank_ = 0;
  int size_ = 1;
  CellTraffic sent_;
  long long exchanges_ = 0;
  // RADMESH_TEST_FAULT=RANK:EXCHANGE:kill|fail (tests): at its EXCHANGE-th portal exchange (1-based),
  // process RANK dies (SIGKILL) or fails its message (MpiError); exchange 0: none.
  long long faultExchange_ = 0;
  bool faultKills_ = false;
};

}  // namespace radmesh::distributed
