#pragma once
// What a mesh program did, counted per operation class. Counts are facts about the program (how
// many hops, messages, operations); docs/emulator-cost-model.md turns them into MP-1 seconds.
#include <cstdint>
#include <string>

namespace radmesh::emu {

// One operation class's counts. Every class uses the same fields so the model prices them alike;
// a field a class never moves stays zero.
struct ClassCounts {
  std::int64_t ops = 0;         // operations issued by the array control unit
  std::int64_t hops = 0;        // xnet: sum of shift distances
  std::int64_t byteHops = 0;    // xnet: sum of distance x bytes moved per PE
  std::int64_t messages = 0;    // router: messages delivered
  std::int64_t rounds = 0;      // router: serialized passes (see routerRounds in router.h)
  std::int64_t byteRounds = 0;  // router: sum of rounds x payload bytes per message
  double flops = 0.0;           // floating-point operations per PE (SIMD: every PE steps them)
  double intOps = 0.0;          // integer/logical operations per PE (compares, adds, moves)
  // Not a fact about the program but about this host: the wall time spent emulating the class's
  // operations (emulator/host_timer.h). The cost model and summary() leave it out.
  double hostSeconds = 0.0;

  ClassCounts& operator+=(const ClassCounts& other);
  ClassCounts& operator-=(const ClassCounts& other);
};

struct CostCounts {
  ClassCounts xnet;    // xnetShift
  ClassCounts router;  // routerSend, routerSendAppend, routerFetch
  ClassCounts alu;     // local computation the program declares (MeshMachine::compute)
  ClassCounts reduce;  // reduceMax, reduceAdd
  ClassCounts scan;    // segmentedScan
  ClassCounts sort;    // sortPairs (its own xnet steps, compare-exchanges and routing)
  std::int64_t maxCollisions = 0;         // most router messages arriving at one PE in one op
  std::int64_t memoryHighWaterBytes = 0;  // per PE

  // Sums difference (for "what did this phase cost"); the two peaks keep this side's values.
  CostCounts operator-(const CostCounts& before) const;
  // Adds the sums; the peaks become the larger of the two.
  CostCounts& operator+=(const CostCounts& other);
  std::string summary() const;  // one line per class, for logs and benchmark labels
};

}  // namespace radmesh::emu
