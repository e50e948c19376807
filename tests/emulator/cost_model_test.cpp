#include "emulator/cost_model.h"

#include <gtest/gtest.h>

#include "emulator/reduce.h"
#include "emulator/router.h"
#include "emulator/scan.h"

namespace radmesh::emu {
namespace {

TEST(CostModel, ReductionsAndScansCostARecursiveDoublingTree) {
  MeshMachine m({8, 8});
  Plural<int> v(m, 1);
  Plural<bool> starts(m, false);
  reduceMax(m, v);
  segmentedScan(m, v, v, starts, ScanKind::Inclusive);
  const CostCounts c = m.costs();
  // Rows then columns, distances 1, 2, 4 each: 6 levels, 14 hops.
  EXPECT_EQ(c.reduce.ops, 1);
  EXPECT_EQ(c.reduce.hops, 14);
  EXPECT_EQ(c.reduce.byteHops, 14 * 8);  // value and index travel together
  EXPECT_EQ(c.reduce.intOps, 6.0);
  EXPECT_EQ(c.scan.hops, 28);  // up and down sweeps
  EXPECT_EQ(c.scan.byteHops, 28 * 5);  // value and segment flag
  EXPECT_EQ(c.scan.intOps, 12.0 + 2.0);  // 2 x 6 combines, plus the local pass and fix-up
}

TEST(CostModel, SecondsAreLinearInTheCountsWithPublishedRates) {
  ClassCounts c;
  c.byteHops = 4096;  // one byte-hop per PE at 5.7 GB/s over 4096 PEs: 4096 * 4096 / 5.7e9 s
  c.byteRounds = 1250;  // 1.25 MB/s per cluster port
  c.rounds = 10;        // ten 2-byte route headers
  c.flops = 75.0;       // 75 KFlops per PE
  c.intOps = 1562.5;    // 6400 Mop/s over 4096 PEs
  const double expected = 4096.0 * 4096.0 / 5.7e9 + (1250.0 + 20.0) / 1.25e6 + 1e-3 + 1e-3;
  EXPECT_NEAR(emulatedSeconds(c), kTable11Calibration * expected, 1e-15);
}

TEST(CostModel, PhaseDifferencesSubtractCounts) {
  MeshMachine m({4, 4});
  Plural<int> v(m), to(m, 0);
  routerSend(m, v, v, to, Combine::Add);
  const CostCounts before = m.costs();
  routerSend(m, v, v, to, Combine::Max);
  const CostCounts phase = m.costs() - before;
  EXPECT_EQ(phase.router.ops, 1);
  EXPECT_EQ(phase.router.messages, 16);
  EXPECT_EQ(phase.router.rounds, 16);
  EXPECT_EQ(phase.maxCollisions, 16);
}

}  // namespace
}  // namespace radmesh::emu

namespace radmesh::emu {
namespace {

TEST(CostCounts, AddingSumsCountsAndKeepsTheLargerPeaks) {
  CostCounts a, b;
  a.xnet.byteHops = 5, a.maxCollisions = 3, a.memoryHighWaterBytes = 100;
  b.xnet.byteHops = 7, b.maxCollisions = 2, b.memoryHighWaterBytes = 300, b.alu.flops = 1.5;
  a += b;
  EXPECT_EQ(a.xnet.byteHops, 12);
  EXPECT_EQ(a.alu.flops, 1.5);
  EXPECT_EQ(a.maxCollisions, 3);
  EXPECT_EQ(a.memoryHighWaterBytes, 300);
}

}  // namespace
}  // namespace radmesh::emu
