#pragma once
// The cells solve (the paper's section 1.7, docs/cells.md): one ProgressiveSolver per cell, over
// the cell's patches and its portal patches (each portal meshed like a wall and turned to face
// into the cell). A shot projects only its cell. Light reaching a portal patch waits there, by
// direction bin; at fixed exchange points it moves to the twin patch facing into the neighbour
// cell, which shoots each bin on into its own directions (or all diffusely, without bins). Between
// exchanges the cells shoot in parallel, each on its own, so results are bitwise the same for any
// number of threads. Lights without a patch (KHR, the sun) shoot once over the whole building when
// the solver is made; each cell receives what landed on its patches.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "parallel/thread_pool.h"
#include "solver/cells/cell_partition.h"
#include "solver/meshing/elements.h"
#include "solver/radiosity/cell_ranks.h"
#include "solver/radiosity/progressive_solver.h"

namespace radmesh {

// Throws OptionError for options the cells solve does not run with (a back end other than native):
// radmesh solve, bench and the viewer refuse alike.
void requireCellsOptions(const SolveOptions& options);

constexpr int kMaxPortalBins = 16;  // CellSolveSettings::portalBins: 16 x 16 on top, 768 bins in all

struct CellSolveSettings {
  double cellM = 0.381;    // the grid the portals are meshed on: the scene's (meshScene's cellM)
  // A round's budget between two portal exchanges: exchangeShots a cell (with a focus, halved at
  // each portal of distance from it), shared by the cells in proportion to their unshot power.
  int exchangeShots = 16;
  // Light crossing a portal keeps its direction in directionBinCount(portalBins) bins and goes on
  // in it (solver/formfactors/direction_bins.h); 0 or 1: re-emitted diffusely. At most 16. 4 by
  // default: a room lit through its door is +6 % off the whole solve with 4 x 4 (+4 % with 8 x 8,
  // at up to 2.6 times the time), +29 % diffuse (docs/cells.md, Directional portals).
  int portalBins = 4;
};

// Throws OptionError naming --portal-bins and its range for a count of bins out of it.
void checkPortalBins(int portalBins);

struct CellFigures {
  std::string name;
  int patches = 0;        // the cell's own
  int elements = 0;       // its own patches' receivers (SolveOptions::subdivide; the patches when off)
  int portalPatches = 0;  // facing into it
  int iterations = 0;
  Ledger ledger;          // the cell's: portalOut counts what reached its portals, waiting or moved
  double waitingW = 0.0;  // reached its portals since the last exchange, not yet moved
};

// Throws SceneError for a partition that does not fit the patches (a cell index out of range, a
// portal joining a cell to itself, a portal that is not a polygon), and what ProgressiveSolver
// throws. A patch of kOutsideCell goes into a cell "outside" of its own, without portals.
//
// Given `ranks` (a process of a distributed solve, docs/cells.md): the cells are assigned to the
// processes (owner(), assignCellsToRanks with a cell's load its patches and portal patches times
// 1 + cells x its share of the light it starts with), and this process makes and solves only its
// own. Every process must call the constructor, round() and radiosity() / displayRadiosity()
// together; everything else reads every cell's figures as of the last round, the same on every
// process, so every process schedules the same rounds, and the answer equals the solve without
// ranks bit for bit.
// A portal patch of `cell` whose power moves to its twin in `twinCell`: the length of its runs of
// lit bins at each exchange (appendPortalRuns), what it sends to another process (or would, were
// the two cells on two), before portalMessage's choice of the shorter for a whole message.
struct PortalLinkTraffic {
  int cell = 0;
  int twinCell = 0;
  std::vector<int> runDoubles;  // per exchange (round)
};

class CellSolver {
 public:
  CellSolver(const Scene& scene, std::vector<Patch> patches, const CellPartition& partition,
             const SolveOptions& options, const CellSolveSettings& settings, CellRanks* ranks = nullptr);
  ~CellSolver();
  CellSolver(const CellSolver&) = delete;
  CellSolver& operator=(const CellSolver&) = delete;

  // The cells shoot their shares of the round's budget (CellSolveSettings::exchangeShots), in
  // proportion to their unshot power; a cell with more than 1/cells of the stopping threshold
  // unshot shoots at least once, and so does the strongest. The cells run in parallel on
  // options.threads, the longest started first; then the power waiting on portals moves to the twins, in cell and patch
  // order. The building's ledger is checked before and after the exchange.
  void round();
  // The building's unshot power (with what waits on portals) at most options.untilUnshot of the
  // emitted, or at most kLedgerTolerance of it, options.maxIterations shot (checked between
  // rounds), or nothing left anywhere.
  bool done() const;
  bool exhausted() const;
  // A new stopping rule for the solve under way (the viewer's panel): throws OptionError for a
  // value out of range.
  void setUntilUnshot(double untilUnshot);
  // Every cell's ProgressiveSolver::dropFormFactorCache (those this process solves).
  void dropFormFactorCaches();
  // The camera's cell: a cell's unshot power and its part of the round's budget count half for each
  // portal between it and the focus, and the cells are started in that order. -1: no focus.
  void focus(int cell);
  int portalDistance(int cell) const;  // from the focus (0 without one); -1 where no portal leads

  // The building's: unshot includes the power waiting on portals, portalIn and portalOut are 0
  // (inside the building they cancel), so emitted = absorbed + unshot + notCaptured + escaped.
  Ledger ledger() const;
  int iterations() const;  // over all cells
  int rounds() const;
  std::vector<Rgb> radiosity() const;         // per patch of the building, W/m^2
  std::vector<Rgb> displayRadiosity() const;  // with each cell's display-only ambient term
  const std::vector<Patch>& patches() const;
  // The building's receivers (options.subdivide): each patch's elements in its cell's solve, patch
  // by patch in the building's order, with the patch each came from (Elements::level empty then);
  // with subdivide off, the patches. Each element's B, and with its cell's display-only ambient
  // term. On every process of a distributed solve together.
  Elements elements() const;
  std::vector<Rgb> elementRadiosity() const;
  std::vector<Rgb> displayElementRadiosity() const;
  int cellCount() const;  // with the outside cell, if any patch faces no cell
  int portalCount() const;
  std::vector<CellFigures> cellFigures() const;
  int owner(int cell) const;  // the process solving the cell (0 without ranks)
  std::vector<double> cellLoads() const;  // per cell: the load the cells were assigned to processes by
  // Per portal link, in the exchanges' order (by cell, then patch), every exchange so far; the
  // same on every process, which must all call it together (docs/scaling.md's model).
  std::vector<PortalLinkTraffic> portalTraffic() const;
  std::size_t figureDoubles() const;  // every cell's figures, shared by all processes twice a round
  // Throws std::out_of_range for a cell another process solves.
  const ProgressiveSolver& cellSolver(int cell) const;
  const SolveOptions& options() const;
  const CellSolveSettings& settings() const;

  // For checkpoints (solver/radiosity/checkpoint.h):
  bool solvesHere(int cell) const;  // this process solves the cell (every cell without ranks)
  bool writesHere() const;          // process 0, or no ranks: the one process that writes files
  const Ledger& lightsLedger() const;  // the lights' shots less what they handed to the cells
  // perCell[c] as given by the process solving cell c, every cell's on process 0; elsewhere
  // perCell unchanged. Every process calls it together.
  std::vector<std::string> gatherOnFirst(std::vector<std::string> perCell) const;
  // Goes on from a saved solve: its rounds and lights' ledger, and restoreCell(c, solver) for each
  // of this process's cells; then every cell's figures are shared. Every process calls it together.
  void restoreProgress(int rounds, const Ledger& lights,
                       const std::function<void(int cell, ProgressiveSolver& solver)>& restoreCell);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace radmesh
