#pragma once
// What the solver thread publishes for the UI: an immutable picture of the solve after some
// iteration. The UI keeps a shared_ptr to the newest one; nothing in it changes after publication.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "solver/bake/display_radiosity.h"
#include "solver/cells/cell_partition.h"
#include "solver/projection/item_buffer.h"
#include "solver/backends/shot_stats.h"
#include "solver/radiosity/progressive_solver.h"
#include "solver/meshing/scene_summary.h"
#include "solver/scene/solve_options.h"

namespace radmesh {

// What a (re)start of the solve is made from: the options, and the grid for meshing.
struct SolveSetup {
  SolveOptions options;
  double cellM = 0.381;  // the paper's 15-inch grid (solver/meshing/meshing.h)
  // --cache-mb as given; unset: the back end's default. Each start sizes options'
  // formFactorCacheBytes from it for the back end it runs on, so a switch in the panel gets its own.
  std::optional<double> cacheMb;
  // --cells auto: the rooms solved cell by cell (CellSolver, docs/cells.md), the camera's first;
  // a step is then a round of every cell's shots and a portal exchange.
  bool cells = false;
  int exchangeShots = 16;  // with cells: the camera's cell's shots a round (CellSolveSettings)
  int portalBins = 4;      // with cells: direction bins of light crossing a portal (CellSolveSettings)
};

// One point per iteration of the curves the panel draws.
struct ConvergencePoint {
  int iteration = 0;
  double convergence = 0.0;      // C after this iteration
  double unshotFraction = 0.0;   // unshot power / emitted after this iteration
  double hostSeconds = 0.0;      // solve time up to and including this iteration
  double machineSeconds = 0.0;   // the back end's machine time so far (ShotStats; else 0)
  std::shared_ptr<const ShotStats> shot;  // this iteration's; null without figures or on a cache hit
};

// Where a cells solve stands: per cell, and which cell it solves first.
struct CellsProgress {
  struct Row {
    std::string name;
    int iterations = 0;
    double unshotFraction = 0.0;  // of the light the cell has had (emitted in it, or through portals)
    int portalDistance = 0;       // from the focus; -1 where no portal leads
  };
  std::vector<Row> cells;  // the partition's, then "outside" if any patch faces no cell
  int rounds = 0;
  int focus = -1;  // the cell solved first: the eye's, else the one nearest it; -1 before an eye is known
  bool eyeInFocus = false;  // the eye stands in the focused cell (not outside every cell)
  std::shared_ptr<const CellPartition> partition;  // the cells' bounds, the same for a whole solve
  std::shared_ptr<const std::vector<int>> cellOfReceiver;  // per receiver of the mesh (patch or element): its cell
};

struct SolverSnapshot {
  std::uint64_t generation = 0;              // counts restarts: a new mesh when it changes
  SolveSetup setup;
  std::shared_ptr<const DisplayMesh> mesh;   // null while meshing, or when setup failed
  SceneSummary summary;
  std::size_t receivers = 0;                 // what receives light: the elements, or the patches
  std::vector<Effect> effects;               // the solver's effects plan: each on or off, and why
  std::vector<Rgb> vertexB;                  // display radiosity per mesh vertex
  double exposure = 1.0;                     // autoExposure of vertexB (viewer/exposure.h)
  std::vector<int> lastShooters;             // patches shot by the last iteration
  std::vector<int> lastShooterElements;      // their elements (the mesh's), to highlight
  std::vector<ConvergencePoint> curve;       // one point per iteration so far
  Ledger ledger;
  bool sceneClosed = false;                  // no open edges: light may not leave (lostLightWarnings)
  double lastCapturedFraction = 0.0;         // of the last iteration's shooters
  // The single plane's item buffer of the last iteration's first shooter, when the UI asked for
  // it (SolverThread::setItemBufferWanted); may lag a few iterations behind while playing.
  std::shared_ptr<const ItemBuffer> itemBuffer;
  int itemBufferShooter = -1;
  // The back end's figures of the last shot there was (cache hits have none): on the mesh, depth
  // histograms at stages (a), (b) and emulated phase costs.
  std::shared_ptr<const ShotStats> lastShotStats;
  std::shared_ptr<const CellsProgress> cells;  // a cells solve's; null for the whole scene's
  bool playing = false;
  int stepsLeft = 0;       // of the steps asked for, those not yet taken
  bool done = false;       // the stopping rule is met (steps may still go past it)
  bool exhausted = false;  // nothing is left to shoot
  // Why the last restart or iteration failed (nothing of that solve is shown), else empty.
  std::string error;
  // It was a SceneError or an OptionError (a bad --cell, a checkpoint of another solve): the user's
  // to fix, which radmesh solve exits 2 for.
  bool errorIsInput = false;
  std::string checkpointMessage;  // the last checkpoint saved (or resumed from), or why not
  bool checkpointFailed = false;  // the last save failed: the message says why and the fix

  int iteration() const { return curve.empty() ? 0 : curve.back().iteration; }
  double convergence() const { return curve.empty() ? 0.0 : curve.back().convergence; }
  double hostSeconds() const { return curve.empty() ? 0.0 : curve.back().hostSeconds; }
};

}  // namespace radmesh
