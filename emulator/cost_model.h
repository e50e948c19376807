#pragma once
// Emulated MasPar MP-1 seconds from operation counts. Figures and their sources are in
// docs/emulator-cost-model.md; the model is linear in the counts and has no cycle-level detail.
#include "emulator/cost_counts.h"

namespace radmesh::emu {

// Published figures for the 4096-PE MP-1 (model MP1104) and the one assumption beside them. All
// are rates, so the 12.5 MHz clock enters only through them.
struct Mp1Figures {
  double flopsPerSecondPerPe = 75e3;          // paper, section 1.4: "about 75 KFlops" per PE
  double intOpsPerSecondPerPe = 6.4e9 / 4096;  // 6400 Mop/s (32-bit) for 4096 PEs
  double xnetBytesPerSecondPerPe = 5.7e9 / 4096;  // 5.7 GB/s aggregate xnet for 4096 PEs
  double routerBytesPerSecondPerPort = 320e6 / 256;  // 320 MB/s over 256 cluster ports
  double routerHeaderBytes = 2.0;  // assumption: a 12-bit PE address opens each route
};

// The one point of Table 1.1 the model may be calibrated on later multiplies every emulated
// second by this factor. 1.0 means uncalibrated: every figure is a prediction.
inline constexpr double kTable11Calibration = 1.0;

struct EmulatedSeconds {
  double xnet = 0.0;
  double router = 0.0;
  double alu = 0.0;
  double reduce = 0.0;
  double scan = 0.0;
  double sort = 0.0;
  double total() const { return xnet + router + alu + reduce + scan + sort; }
};

double emulatedSeconds(const ClassCounts& counts, const Mp1Figures& figures = {});
EmulatedSeconds emulatedSeconds(const CostCounts& counts, const Mp1Figures& figures = {});

}  // namespace radmesh::emu
