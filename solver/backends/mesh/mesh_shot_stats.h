#pragma once
// What one shot of the mesh back end did (in a solve, one iteration: the shooter selection, the
// shot and the radiosity update): the item-buffer depths at the paper's points (a) and (b) of
// section 1.6.1, counted from what actually arrived at each PE, and the emulated machine's counts
// and MP-1 seconds per phase of section 1.5.
#include <chrono>
#include <string>
#include <vector>

#include "emulator/cost_counts.h"
#include "emulator/cost_model.h"
#include "emulator/mesh_machine.h"
#include "solver/backends/shot_stats.h"

namespace radmesh {

struct MeshPhaseCost {
  std::string name;           // "projection", "route (a)", "spread down (b)", ...
  emu::CostCounts counts;     // what the phase's mesh program did
  double emulatedSeconds = 0.0;
  double hostSeconds = 0.0;   // wall time the emulation of the phase took here
};

struct MeshShotStats {
  std::vector<int> depthA;      // per PE: descriptions routed to it at stage (a)
  std::vector<int> depthB;      // per PE: descriptions it holds after the downward spread (b)
  int passes = 1;               // scan-conversion passes the PEs' memory needed (see MeshScanConversion)
  int depthAMax = 0;
  int depthBMax = 0;
  std::vector<int> depthAHist;  // [d]: how many PEs had depth d at (a)
  std::vector<int> depthBHist;
  std::vector<MeshPhaseCost> phases;
  emu::CostCounts counts;       // the whole shot
  double emulatedSeconds = 0.0;
  double hostSeconds = 0.0;
};

// Adds the emulated cost and host time of a phase, from construction to destruction, to the
// stats' phase of that name (a phase run in several passes adds up).
class PhaseClock {
 public:
  PhaseClock(const emu::MeshMachine& machine, MeshShotStats& stats, std::string name);
  ~PhaseClock();
  PhaseClock(const PhaseClock&) = delete;
  PhaseClock& operator=(const PhaseClock&) = delete;

 private:
  const emu::MeshMachine& machine_;
  MeshShotStats& stats_;
  std::string name_;
  emu::CostCounts before_;
  std::chrono::steady_clock::time_point start_;
};

// The shot as every consumer sees it (solver/backends/shot_stats.h): the emulated MP-1 seconds,
// and as figures the depths' maxima and histograms (the per-PE lists left out: the histograms say
// the same in far less), the passes, the op counts and host seconds per operation class, and the
// phases' emulated and host seconds.
ShotStats shotStats(const MeshShotStats& stats);

// Histogram of depths: hist[d] = how many entries equal d (d from 0 to the maximum).
std::vector<int> depthHistogram(const std::vector<int>& depths);

}  // namespace radmesh
