#pragma once
// `--cells auto` (docs/cells.md): the building's rooms found from its geometry and solved cell by
// cell, for solve, render and bench.
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "solver/radiosity/cell_solver.h"

namespace radmesh::cli {

// The cells of the meshed scene (findCells) and their solver; prints how many cells and portals.
// With `ranks`, this process's part of a distributed solve (CellSolver).
std::unique_ptr<CellSolver> makeCellSolver(const Scene& scene, std::vector<Patch> patches, const SolveOptions& options,
                                           const CellSolveSettings& settings, CellRanks* ranks = nullptr);
// Rounds until done(), with progress on stdout unless `quiet`, calling afterRound (if any) with
// the wall seconds so far after each round; returns the wall seconds.
double solveCellsWithProgress(CellSolver& solver, bool quiet,
                              const std::function<void(double seconds)>& afterRound = {});
// The summary lines of a cells solve: patches, cells, portals, iterations, the building's ledger.
void printCellsSummary(const CellSolver& solver, double seconds);
// The `--stats` document of a cells solve: "cells", "portals", the building's ledger and "per_cell";
// `seconds` are this run's, after the `resumedAt` iterations a checkpoint brought (0: none).
nlohmann::json cellsStats(const CellSolver& solver, const std::string& scene, double seconds, int resumedAt);
// One process of a distributed solve.
struct RankFigures {
  int cells = 0;
  int patches = 0;  // its cells', own and portal
  long long shots = 0;
  double work = 0.0;  // the load model's units: shots times the cell's patches (patch shots)
  CellTraffic sent;
  double wallSeconds = 0.0;  // where the caller timed it
};
// Every process's figures, by rank, from the solver's cells and each process's `traffic`.
std::vector<RankFigures> rankFigures(const CellSolver& solver, const std::vector<CellTraffic>& traffic);
// A distributed solve's "distributed": per rank its RankFigures (without the wall time), what it
// sent in all and per round; "owner": each cell's rank.
nlohmann::json distributedStats(const CellSolver& solver, const std::vector<CellTraffic>& traffic);

}  // namespace radmesh::cli
