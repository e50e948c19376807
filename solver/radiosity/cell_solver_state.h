#pragma once
// The state of a CellSolver, shared by the files that implement it (cell_solver_setup.cpp: the
// cells, portals and lights made once; cell_solver.cpp: the rounds; cell_solver_gather.cpp: the
// building's radiosity and elements); private to solver/radiosity.
#include <memory>
#include <string>
#include <vector>

#include "solver/formfactors/form_factor_row.h"
#include "solver/radiosity/cell_solver.h"

namespace radmesh {
namespace cell_state {

// Power reaching `patch` of `cell` moves, at the next exchange, to `twinPatch` of `twinCell`.
struct PortalLink {
  int cell = 0;
  int patch = 0;
  int twinCell = 0;
  int twinPatch = 0;
};

struct CellState {
  std::string name;
  std::vector<int> buildingPatch;  // per own patch (the first of the cell solve's): the building's index
  int portalPatches = 0;           // after the own ones
  std::unique_ptr<ProgressiveSolver> solver;  // none where another process solves the cell
};

// One light's shot over the whole building (CellSolver::State::shootLights), cut by cell.
struct LightShot {
  Rgb power;
  FormFactorRow row;
  std::vector<FormFactorRow> perCell;
};

// The elements of the first `patches` patches of a solve (a cell's own, before its portal patches).
inline int elementCount(const ProgressiveSolver& solver, int patches) {
  std::vector<int> own(static_cast<size_t>(patches));
  for (int k = 0; k < patches; ++k) own[k] = k;
  return static_cast<int>(solver.elementsOf(own).size());
}

// A cell's figures as the schedule, the building's ledger and the stats read them, in doubles for
// CellRanks: its ledger, iterations, whether it is exhausted, its own patches' elements, its
// emitting patches yet to shoot, then what waits on each of its links.
constexpr size_t kFigures = Ledger::kTerms.size() + 4;

inline std::vector<double> packFigures(const ProgressiveSolver& solver, int ownPatches, std::vector<double> waitingW) {
  std::vector<double> out;
  for (double Ledger::*term : Ledger::kTerms) out.push_back(solver.ledger().*term);
  out.insert(out.end(), {static_cast<double>(solver.history().size()), solver.exhausted() ? 1.0 : 0.0,
                         static_cast<double>(elementCount(solver, ownPatches)),
                         static_cast<double>(solver.emittersToShoot())});
  out.insert(out.end(), waitingW.begin(), waitingW.end());
  return out;
}

}  // namespace cell_state

struct CellSolver::State {
  Scene building;  // what the lights shoot over (lightRowOverCell)
  std::vector<Patch> patches;
  SolveOptions options;
  CellSolveSettings settings;
  std::vector<cell_state::CellState> cells;
  std::vector<int> cellOf;  // per building patch: its cell (the outside's the last)
  std::vector<cell_state::PortalLink> links;  // by cell, then patch: the exchange order
  std::vector<size_t> firstLink;  // per cell, and one past the last: where its links start
  std::vector<std::vector<int>> neighbours;
  int portalCount = 0;
  int focus = -1;
  std::vector<int> distance;  // from the focus, -1 where no portal leads
  int rounds = 0;
  // The lights' shots (State::shootLights) less what they handed to the cells: escaped, the backs
  // of one-sided patches. Part of the building's ledger, in no cell's.
  Ledger lights;
  ThreadPool pool;
  CellRanks* ranks;
  std::vector<double> load;  // per cell: what assignCellsToRanks cut by
  std::vector<int> owner;    // per cell: the process solving it
  std::vector<std::vector<int>> linkRunDoubles;  // per exchange, per link: its runs' length (exchange())
  // Every cell's figures as of the last refresh(), the same on every process: what the schedule,
  // done() and the building's ledger read.
  std::vector<Ledger> cellLedger;
  std::vector<int> cellIterations;
  std::vector<char> cellExhausted;
  std::vector<int> cellElements;
  std::vector<int> cellEmittersToShoot;
  std::vector<double> waitingW;  // per link: what waits on its portal patch, W

  State(const Scene& b, std::vector<Patch> p, const SolveOptions& o, const CellSolveSettings& s, CellRanks* r)
      : building(b), patches(std::move(p)), options(o), settings(s), pool(o.threads), ranks(r) {}

  bool owns(int cell) const { return owner[cell] == (ranks ? ranks->rank() : 0); }

  // Portals from the focus, 30 where none leads (a cell's weight halves with each).
  int hops(int cell) const { return distance[cell] < 0 ? 30 : std::min(distance[cell], 30); }
  std::vector<int> shotsThisRound(const Ledger& building) const;
  void exchange();
  std::vector<cell_state::LightShot> shootLights(const Scene& scene);
  void receiveLights(const std::vector<cell_state::LightShot>& shots);
  FormFactorRow lightRowOverCell(int cell, int light, const std::vector<Patch>& receivers);
  void refresh();
  template <typename PerCell>
  std::vector<Rgb> gatherPatches(PerCell perCell) const;
  template <typename Write, typename Read>
  void gatherElements(size_t width, Write write, Read read) const;
  template <typename PerElement>
  std::vector<Rgb> gatherElementRadiosity(PerElement perElement) const;
};

}  // namespace radmesh
