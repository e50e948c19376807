// Where the emulator's host time goes: each operation's wall time lands in its own class, and an
// operation that runs others inside it (a sort's routing, a router call's PE loops) is charged once.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "emulator/mesh_sort.h"
#include "emulator/xnet.h"
#include "tests/emulator/plural_compare.h"

namespace radmesh::emu {
namespace {

TEST(HostTime, OnlyTheOutermostTimerCharges) {
  bool running = false;
  double outer = 0.0, inner = 0.0;
  {
    const HostTimer a(running, outer);
    EXPECT_TRUE(running);
    {
      const HostTimer b(running, inner);
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    EXPECT_TRUE(running) << "the inner timer must not end the outer one";
  }
  EXPECT_FALSE(running);
  EXPECT_GE(outer, 0.002);
  EXPECT_EQ(inner, 0.0);
}

TEST(HostTime, EachOperationChargesItsOwnClass) {
  MeshMachine m({32, 32});
  Plural<int> k(m), v(m);
  test::load(k, test::randomInts(1024, 0, 1000, 5));
  sortPairs(m, k, v);
  const CostCounts afterSort = m.costs();
  EXPECT_GT(afterSort.sort.hostSeconds, 0.0);
  // The sort's own exchanges and local steps are the sort's time, not the xnet's or the ALU's.
  EXPECT_EQ(afterSort.xnet.hostSeconds, 0.0);
  EXPECT_EQ(afterSort.alu.hostSeconds, 0.0);
  EXPECT_EQ(afterSort.router.hostSeconds, 0.0);
  xnetShift(m, v, k, Direction::E, 3);
  m.compute({1.0, 0.0}, [&](int pe) { v[pe] += 1; });
  const CostCounts after = m.costs();
  EXPECT_GT(after.xnet.hostSeconds, 0.0);
  EXPECT_GT(after.alu.hostSeconds, 0.0);
  EXPECT_EQ(after.sort.hostSeconds, afterSort.sort.hostSeconds);
  // A phase's difference keeps host time; the summary (a fact about the program) leaves it out.
  EXPECT_EQ((after - afterSort).sort.hostSeconds, 0.0);
  EXPECT_EQ(after.summary().find("host"), std::string::npos);
}

}  // namespace
}  // namespace radmesh::emu
