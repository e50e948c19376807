#pragma once
// The seam between a cells solve and the processes it is split over (`--distributed`; distributed/
// implements it over MPI, so the solver never includes MPI). Every process holds the whole
// partition and knows which process solves each cell (assignCellsToRanks); it solves only its own
// cells and asks the others for two things: every cell's figures (to schedule the rounds and sum
// the ledger in cell order, the same numbers on every process) and the power on the portals its
// cells share with theirs.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

// What one process sent to the others: its neighbour messages (portal power) and its part of the
// all-gathers (every cell's figures), counted in payload bytes, as often as it went out; and the
// wall time it spent in those calls, waiting for the others included (where imbalance shows).
struct CellTraffic {
  long long messages = 0;
  long long bytes = 0;
  long long gathers = 0;
  long long gatherBytes = 0;
  double waitSeconds = 0.0;
};

CellTraffic operator-(const CellTraffic& after, const CellTraffic& before);

class CellRanks {
 public:
  virtual ~CellRanks() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  // perCell[c] has the same length on every process, and this process has filled the cells it
  // solves (owner[c] == rank()); on return every process has every cell's, as its owner filled them.
  virtual void shareCells(const std::vector<int>& owner, std::vector<std::vector<double>>& perCell) = 0;
  // With every process r this one hears from (incomingLimits[r] > 0; neighbours are mutual, a
  // portal's links going both ways): sends it outgoing[r], even empty, and receives at most
  // incomingLimits[r] doubles from it; returns what came, by process. Only neighbours talk.
  virtual std::vector<std::vector<double>> exchange(const std::vector<std::vector<double>>& outgoing,
                                                    const std::vector<std::size_t>& incomingLimits) = 0;
  // Every process's bytes, by rank, on process 0; empty elsewhere (all must call it together).
  // A checkpoint's cells: not counted in traffic().
  virtual std::vector<std::string> gatherOnFirst(const std::string& bytes) = 0;
  // Process 0's flag on every process (all must call it together): a decision on one clock.
  virtual bool firstSays(bool flag) = 0;
  // Every process's traffic so far, by rank, on every process (all must call it together).
  virtual std::vector<CellTraffic> traffic() = 0;
  // Every process's `value`, by rank, on every process (all must call it together; not counted).
  virtual std::vector<double> allGather(double value) = 0;
};

// How portal power travels in a message between processes. A link's runs: only the runs of its
// bins carrying light, each as its first position (the link's place among the message's links x
// bins + the bin), its length, then its bins' r, g, b; nothing for a dark link. A message holds its
// links' runs where they are shorter than the full bins (3 doubles each), else the full bins: it is
// empty when its portals are dark, and never longer than the full bins (which the receiver knows).
// appendPortalRuns returns the doubles it appended.
std::size_t appendPortalRuns(std::span<const Rgb> bins, std::size_t link, std::vector<double>& message);
// A message's length from its links' runs' and its full bins' (portalMessage's choice).
std::size_t portalMessageDoubles(std::size_t runDoubles, std::size_t fullBins);
// The message of `runs` (its links' appendPortalRuns) or `fullBins` (every link's bins in order).
std::vector<double> portalMessage(std::vector<double> runs, std::span<const Rgb> fullBins);
// A message of `links` links of `bins` bins back to every bin, zero where no run was. Throws
// std::runtime_error for a run that does not fit in them.
std::vector<Rgb> readPortalMessage(const std::vector<double>& message, std::size_t links, std::size_t bins);

// Which process solves each cell: the cells in their order, cut into `ranks` runs of about equal
// load, so that a process's cells are neighbours and it talks to few others. A cell goes to the
// run its load's midpoint falls in. Deterministic; a run may be empty.
std::vector<int> assignCellsToRanks(const std::vector<double>& load, int ranks);

}  // namespace radmesh
