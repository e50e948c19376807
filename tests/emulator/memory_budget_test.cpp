#include "emulator/memory_ledger.h"

#include <gtest/gtest.h>

#include "emulator/pe_array.h"
#include "emulator/plural.h"

namespace radmesh::emu {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(MemoryBudget, PluralsReserveTheirSizeOnEveryPeAndReleaseIt) {
  MeshMachine m({4, 4});
  {
    Plural<double> a(m);
    Plural<int> b(m);
    EXPECT_EQ(m.memory().usedBytes(), 12);
    Plural<double> c = a;
    EXPECT_EQ(m.memory().usedBytes(), 20);
  }
  EXPECT_EQ(m.memory().usedBytes(), 0);
  EXPECT_EQ(m.costs().memoryHighWaterBytes, 20);
}

TEST(MemoryBudget, ExceedingItNamesThePeTheBytesTheBudgetAndTheFix) {
  MeshMachine m({8, 8, /*memoryBudgetBytes=*/1024});
  Plural<double> held(m, 0.0, "held");  // 8 bytes
  PeArray<std::int32_t> queue(m, "item buffer");
  for (int i = 0; i < 254; ++i) queue.push(19, i);  // 8 + 1016 = 1024: exactly the budget
  try {
    queue.push(19, 254);
    FAIL() << "expected MemoryBudgetError";
  } catch (const MemoryBudgetError& e) {
    const std::string what = e.what();
    EXPECT_TRUE(contains(what, "PE (row 2, col 3)")) << what;
    EXPECT_TRUE(contains(what, "needs 1028 bytes")) << what;
    EXPECT_TRUE(contains(what, "'item buffer'")) << what;
    EXPECT_TRUE(contains(what, "budget is 1024 bytes")) << what;
    EXPECT_TRUE(contains(what, "Fix:")) << what;
    EXPECT_EQ(e.pe(), 19);
    EXPECT_EQ(e.neededBytes(), 1028);
    EXPECT_EQ(e.budgetBytes(), 1024);
  }
  EXPECT_EQ(queue.count(19), 254);  // nothing half-done
  EXPECT_EQ(m.memory().usedBytes(), 1024);
}

TEST(MemoryBudget, ListsChargeTheLongestListOnEveryPe) {
  MeshMachine m({4, 4});
  PeArray<std::int64_t> lists(m, "lists");
  lists.push(3, 1);
  lists.push(3, 2);
  lists.push(9, 3);
  EXPECT_EQ(lists.reservedLength(), 2);
  EXPECT_EQ(m.memory().usedBytes(), 16);
  lists.clearAll();  // a declared array keeps its room
  EXPECT_EQ(m.memory().usedBytes(), 16);
}

TEST(MemoryBudget, GrowingInsideAParallelStepIsRefused) {
  MeshMachine m({4, 4, 16 * 1024, 2});
  PeArray<int> lists(m, "lists");
  EXPECT_THROW(m.compute({1e6, 0}, [&](int pe) { lists.pushReserved(pe, 1); }), std::logic_error);
}

}  // namespace
}  // namespace radmesh::emu
