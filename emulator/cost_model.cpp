#include "emulator/cost_model.h"

namespace radmesh::emu {

double emulatedSeconds(const ClassCounts& c, const Mp1Figures& f) {
  // Bit-serial links: an xnet hop moves each PE's bytes over its own link; a router round moves
  // one message (payload + route-opening header) through each cluster port.
  const double xnet = static_cast<double>(c.byteHops) / f.xnetBytesPerSecondPerPe;
  const double router =
      (static_cast<double>(c.byteRounds) + static_cast<double>(c.rounds) * f.routerHeaderBytes) /
      f.routerBytesPerSecondPerPort;
  const double alu = c.flops / f.flopsPerSecondPerPe + c.intOps / f.intOpsPerSecondPerPe;
  return kTable11Calibration * (xnet + router + alu);
}

EmulatedSeconds emulatedSeconds(const CostCounts& c, const Mp1Figures& f) {
  return {emulatedSeconds(c.xnet, f),   emulatedSeconds(c.router, f),
          emulatedSeconds(c.alu, f),    emulatedSeconds(c.reduce, f),
          emulatedSeconds(c.scan, f),   emulatedSeconds(c.sort, f)};
}

}  // namespace radmesh::emu
