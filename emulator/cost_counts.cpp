#include "emulator/cost_counts.h"

#include <algorithm>
#include <sstream>

namespace radmesh::emu {

ClassCounts& ClassCounts::operator+=(const ClassCounts& o) {
  ops += o.ops;
  hops += o.hops;
  byteHops += o.byteHops;
  messages += o.messages;
  rounds += o.rounds;
  byteRounds += o.byteRounds;
  flops += o.flops;
  intOps += o.intOps;
  hostSeconds += o.hostSeconds;
  return *this;
}

ClassCounts& ClassCounts::operator-=(const ClassCounts& o) {
  ops -= o.ops;
  hops -= o.hops;
  byteHops -= o.byteHops;
  messages -= o.messages;
  rounds -= o.rounds;
  byteRounds -= o.byteRounds;
  flops -= o.flops;
  intOps -= o.intOps;
  hostSeconds -= o.hostSeconds;
  return *this;
}

CostCounts CostCounts::operator-(const CostCounts& before) const {
  CostCounts d = *this;
  d.xnet -= before.xnet;
  d.router -= before.router;
  d.alu -= before.alu;
  d.reduce -= before.reduce;
  d.scan -= before.scan;
  d.sort -= before.sort;
  return d;
}

CostCounts& CostCounts::operator+=(const CostCounts& o) {
  xnet += o.xnet;
  router += o.router;
  alu += o.alu;
  reduce += o.reduce;
  scan += o.scan;
  sort += o.sort;
  maxCollisions = std::max(maxCollisions, o.maxCollisions);
  memoryHighWaterBytes = std::max(memoryHighWaterBytes, o.memoryHighWaterBytes);
  return *this;
}

std::string CostCounts::summary() const {
  std::ostringstream out;
  auto line = [&](const char* name, const ClassCounts& c) {
    out << name << ": ops " << c.ops << ", hops " << c.hops << ", byteHops " << c.byteHops
        << ", messages " << c.messages << ", rounds " << c.rounds << ", byteRounds "
        << c.byteRounds << ", flops " << c.flops << ", intOps " << c.intOps << '\n';
  };
  line("xnet", xnet);
  line("router", router);
  line("alu", alu);
  line("reduce", reduce);
  line("scan", scan);
  line("sort", sort);
  out << "maxCollisions " << maxCollisions << ", memoryHighWaterBytes " << memoryHighWaterBytes
      << '\n';
  return out.str();
}

}  // namespace radmesh::emu
