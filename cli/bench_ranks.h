#pragma once
// A distributed `bench solve` (docs/scaling.md): what each process did and sent, and the model that
// extrapolates the run to more processes. The table and the model read only RankFigures and
// RunShape, so another distributed back end (the mesh machine) can fill them from its transport.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/cell_solve.h"
#include "cli/csv.h"
#include "solver/radiosity/cell_solver.h"

namespace radmesh::cli {

// What the model reads of a solve, the same for any number of processes (the answer and its
// schedule are): each cell's shots in each round, its patches and load, every portal link's traffic.
struct RunShape {
  std::vector<std::vector<int>> shotsPerRound;  // [round][cell]
  std::vector<int> cellPatches;                 // own and portal
  std::vector<double> cellLoads;                // assignCellsToRanks cuts by these
  std::vector<PortalLinkTraffic> links;
  int rounds = 0;
  std::size_t bins = 1;      // direction bins a portal patch
  double figureBytes = 0.0;  // every cell's figures, all-gathered twice a round
};

// The model on `ranks` processes (docs/scaling.md, The model).
struct ModelPoint {
  int ranks = 1;
  double maxWork = 0.0;        // the busiest process's patch shots
  double meanWork = 0.0;
  double roundMaxWork = 0.0;   // the sum over rounds of the busiest process's in each round
  int maxMessages = 0;         // neighbour messages of a process a round
  double maxBytesPerRound = 0.0;
  double allBytesPerRound = 0.0;
  double seconds = 0.0;        // the modelled solve: compute, all-gathers, portal exchange
};

struct ClusterModel {
  double latencySeconds = 2e-6;  // a message's
  double bytesPerSecond = 1e9;
  double secondsPerPatchShot = 0.0;  // from the measured run
};

ModelPoint modelPoint(const RunShape& shape, int ranks, const ClusterModel& cluster);

// Prints the per-rank table and the model on kModelRanks processes; returns both as JSON
// ("per_rank", "model") and appends them to the CSV tables (a row per rank, a row per model point).
nlohmann::json reportRanks(const std::vector<RankFigures>& ranks, const RunShape& shape,
                           const std::vector<std::string>& setting, CsvTable& ranksCsv, CsvTable& modelCsv);
CsvTable ranksCsvTable();
CsvTable modelCsvTable();

// docs/scaling.md's figures, PNG_STEM-speedup.png and PNG_STEM-bytes.png: the model's speed-up and
// bytes a round (STEM-model.csv of one run) against the measured ones (the STEM-ranks.csv of runs
// on different numbers of ranks, the same scene and setting).
void drawScalingFigures(const std::string& modelCsv, const std::vector<std::string>& ranksCsvs,
                        const std::string& pngStem);

}  // namespace radmesh::cli
