#pragma once
// The measurements behind docs/performance.md and docs/accuracy.md.
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "solver/io/daylight.h"
#include "solver/radiosity/cell_ranks.h"
#include "solver/scene/solve_options.h"
#include "solver/scene/up_axis.h"

namespace radmesh::cli {

struct BenchSolveArgs {
  std::string scene = "office";
  UpChoice up = UpChoice::Format;
  double metresPerUnit = 0.0;  // --units; 0: not given
  double cellM = 0.381;
  bool cellGiven = false;  // else the cell is chosen from the scene's size
  Daylight daylight;
  std::vector<std::string> projections{"plane", "hemicube"};
  bool projectionsGiven = false;  // else the mesh back end times the plane alone, as `solve` takes it
  std::vector<int> resolutions{64, 128, 256, 512};
  std::vector<int> shooters{1};    // k per iteration
  std::string backend = "native";
  PeMachine machine;  // --pe-grid, --pe-memory (mesh backend)
  double until = 0.95;
  double untilUnshot = 0.0;  // and stop at this unshot fraction (0: no such rule)
  int maxIterations = 5000;
  int threads = 1;
  std::string cellsMode = "off";  // --cells auto: the cells solve (docs/cells.md), timed per iteration
  int exchangeShots = 16;
  int portalBins = 4;    // CellSolveSettings::portalBins
  std::vector<double> cells;  // patch-count scaling sweep; empty: skipped
  int scalingResolution = 256;
  int scalingIterations = 20;
  bool distributed = false;  // --distributed: the cells solve over the mpirun's processes
  std::string csvStem;       // with it: STEM-ranks.csv (a row per process) and STEM-model.csv
  double cacheMb = 0.0;      // --cache-mb: the timed solves' form-factor cache (kBenchCacheMbHelp)
};

// With `ranks`, this process's part of a distributed run (rank 0 alone prints and writes): each
// cells row gains the per-rank figures and the model (cli/bench_ranks.h).
nlohmann::json benchSolve(const BenchSolveArgs& args, CellRanks* ranks = nullptr);

struct AccuracyArgs {
  std::string scene = "office";
  UpChoice up = UpChoice::Format;
  double metresPerUnit = 0.0;  // --units; 0: not given
  std::string name = "office";   // file stem of the outputs
  std::string outDir;            // CSV and plots go here; empty: table only
  Daylight daylight;
  // A room's cells, the paper's 15 inches and one on either side; unless cellsGiven, scaled to the
  // cell the scene's own solve would choose (a 0.55 m box would otherwise be 40 patches at each).
  std::vector<double> cells{0.5, 0.381, 0.25};
  bool cellsGiven = false;
  std::vector<int> resolutions{32, 64, 128, 256, 512, 1024};
  int referenceResolution = 1024;
  // > 0: the pictures' reference is a patch mesh at this cell, finer than any of `cells` and not
  // swept, so that the finest swept mesh is scored too; 0: the finest of `cells` (each swept mesh
  // keeps its own reference for the same-mesh error either way).
  double referenceCellM = 0.0;
  double referenceUntil = 0.999;
  double referenceUnshot = 0.001;  // and at most this fraction of the emitted power unshot
  int maxIterations = 20000;
  int threads = 0;
  std::vector<std::string> projections{"plane", "hemicube"};  // plane: ratios 3 and 5
  // The subdivide axis (docs/accuracy.md): off runs on every cell; uniform and adaptive on
  // subdivideCells (empty: the coarsest), once per --min-element (adaptive: adaptiveMinElements,
  // when given).
  std::vector<std::string> subdivide{"off"};
  std::vector<double> minElements{0.0};
  std::vector<double> adaptiveMinElements;
  std::vector<double> subdivideCells;
  std::vector<std::string> elementRows{"auto"};  // uniform and adaptive run once per value (--element-rows)
  double splitContrast = 0.1;
  double untilUnshot = 0.0;  // > 0: every point also solved on to this unshot fraction, and measured there
  double cacheMb = 0.0;      // --cache-mb: the swept solves' form-factor cache (the references always have one)
};

// --quick: the CI-sized sweep (well under a minute), same code and outputs.
AccuracyArgs quickAccuracyArgs(AccuracyArgs args);
// With an outDir, writes NAME.csv (a row per point) and NAME-traces.csv (error against iteration), then draws them.
nlohmann::json benchAccuracy(const AccuracyArgs& args);
// The plots of docs/accuracy.md, PNGSTEM-*.png, drawn from STEM.csv and STEM-traces.csv; returns the PNGs drawn.
std::vector<std::string> drawAccuracyFigures(const std::string& stem, const std::string& sceneName,
                                             const std::string& pngStem);
struct BenchCellsArgs {
  std::vector<std::string> scenes{"two-rooms", "building:3x3"};
  double cellM = 0.381;
  std::string projection = "hemicube";
  int resolution = 128;
  double untilUnshot = 0.01;   // both solves, the whole building's and the cells'
  double focusUnshot = 0.05;   // the focus cell: its unshot power against the light it has had
  int exchangeShots = 16;
  int portalBins = 4;          // CellSolveSettings::portalBins
  int focusCell = 0;           // the camera's cell
  int maxIterations = 1'000'000;
  bool skipWhole = false;      // no whole-building solve (and so no error per room)
  bool focusOnly = false;      // the focus run alone: no whole-building solve, no solve to untilUnshot
  std::string subdivide = "off";  // both solves' elements (docs/accuracy.md): off, uniform or adaptive
  double minElementM = 0.0;
  double cacheMb = 0.0;  // --cache-mb: both solves' form-factor cache
  int threads = 2;       // --threads: the second cells solve's, beside the first on one (0: every core)
};

// The cells solve beside the whole building's (docs/cells.md): time, iterations, the error of the
// reflected light per room; on one thread and on `threads`; and the focus cell's time to focusUnshot.
nlohmann::json benchCells(const BenchCellsArgs& args);

// --cache-mb of the benches: none by default, so that a setting's time is its own shots.
inline constexpr const char* kBenchCacheMbHelp =
    "Form-factor row cache of every timed solve, MiB (0: none, the default, so that a setting's time is its own "
    "shots; give radmesh solve's budget, e.g. 1024, to time what it runs)";
// What the benches print of it.
inline std::string benchCacheText(double mb) {
  return mb > 0.0 ? fmt::format("a {:g} MiB form-factor cache", mb) : "no form-factor cache (--cache-mb)";
}

// "plane r3", "plane r5", "hemicube": a setting as the tables and plots name it.
std::string settingLabel(const std::string& projection, double ratio);

}  // namespace radmesh::cli
