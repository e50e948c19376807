#include "emulator/active_mask.h"

#include <gtest/gtest.h>

#include "emulator/plural.h"
#include "tests/emulator/plural_compare.h"

namespace radmesh::emu {
namespace {

TEST(ActiveMask, NestedIfElseNarrowsFlipsAndRestores) {
  MeshMachine m({4, 4});
  Plural<bool> even(m), low(m);
  for (int pe = 0; pe < 16; ++pe) even[pe] = pe % 2 == 0, low[pe] = pe < 8;
  Plural<int> tag(m, 0);
  auto mark = [&](int value) { m.compute({0, 1}, [&](int pe) { tag[pe] = value; }); };
  {
    ActiveScope outer(m, even);
    EXPECT_EQ(m.mask().activeCount(), 8);
    {
      ActiveScope inner(m, low);
      mark(1);  // even and low
      inner.elseBranch();
      mark(2);  // even and not low
      EXPECT_EQ(m.mask().activeCount(), 4);
    }
    EXPECT_EQ(m.mask().activeCount(), 8);
    outer.elseBranch();
    mark(3);  // odd
  }
  EXPECT_TRUE(m.mask().allActive());
  std::vector<int> expected(16);
  for (int pe = 0; pe < 16; ++pe) expected[pe] = pe % 2 ? 3 : (pe < 8 ? 1 : 2);
  EXPECT_TRUE(test::samePerPe(m.grid(), tag, expected));
}

TEST(ActiveMask, PopOrFlipWithoutPushIsRefused) {
  ActiveMask mask(4);
  EXPECT_THROW(mask.pop(), std::logic_error);
  EXPECT_THROW(mask.flip(), std::logic_error);
  const bool wrongSize[3] = {true, true, true};
  EXPECT_THROW(mask.push(wrongSize), std::invalid_argument);
}

TEST(ActiveMask, ComputeChargesEveryPeInstructionStreamWhateverTheMask) {
  MeshMachine m({4, 4});
  ActiveScope scope(m, test::randomCondition(m, 0.25, 2));
  m.compute({3.0, 2.0}, [](int) {});
  EXPECT_EQ(m.costs().alu.flops, 3.0);  // SIMD: inactive PEs wait through the same steps
  EXPECT_EQ(m.costs().alu.intOps, 2.0);
  EXPECT_EQ(m.costs().alu.ops, 1);
}

}  // namespace
}  // namespace radmesh::emu
