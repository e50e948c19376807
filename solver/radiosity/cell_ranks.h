#pragma once
// The seam between a cells solve and the processes it is split over (`--distributed`; distributed/
// implements it over MPI, so the solver never includes MPI). Every process holds the whole
// partition and knows which process solves each cell (assignCellsToRanks); it solves only its own
// cells and asks the others for two things: every cell's figures (to schedule the rounds and sum
// the ledger in cell order, the same numbers on every process) and the power on the portals its
// cells share with theirs.
#include <cstddef>
#include <string>
#include <vector>

namespace radmesh {

// What one process sent to the others: its neighbour messages (portal power) and its part of the
// all-gathers (every cell's figures), counted in payload bytes, as often as it went out.
struct CellTraffic {
  long long messages = 0;
  long long bytes = 0;
  long long gathers = 0;
  long long gatherBytes = 0;
};

class CellRanks {
 public:
  virtual ~CellRanks() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  // perCell[c] has the same length on every process, and this process has filled the cells it
  // solves (owner[c] == rank()); on return every process has every cell's, as its owner filled them.
  virtual void shareCells(const std::vector<int>& owner, std::vector<std::vector<double>>& perCell) = 0;
  // Sends outgoing[r] to process r where it is not empty, and receives incomingSizes[r] doubles
  // from every r where that is not 0; returns what came, by process. Only neighbours talk.
  virtual std::vector<std::vector<double>> exchange(const std::vector<std::vector<double>>& outgoing,
                                                    const std::vector<std::size_t>& incomingSizes) = 0;
  // Every process's bytes, by rank, on process 0; empty elsewhere (all must call it together).
  // A checkpoint's cells: not counted in traffic().
  virtual std::vector<std::string> gatherOnFirst(const std::string& bytes) = 0;
  // Process 0's flag on every process (all must call it together): a decision on one clock.
  virtual bool firstSays(bool flag) = 0;
  // Every process's traffic so far, by rank, on every process (all must call it together).
  virtual std::vector<CellTraffic> traffic() = 0;
};

// Which process solves each cell: the cells in their order, cut into `ranks` runs of about equal
// load, so that a process's cells are neighbours and it talks to few others. A cell goes to the
// run its load's midpoint falls in. Deterministic; a run may be empty.
std::vector<int> assignCellsToRanks(const std::vector<double>& load, int ranks);

}  // namespace radmesh
