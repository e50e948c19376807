#include "emulator/scan.h"

#include <gtest/gtest.h>

#include "tests/emulator/plural_compare.h"

namespace radmesh::emu {
namespace {

using test::samePerPe;

// Scalar segmented scan over a sequence with per-element start flags and participation.
std::vector<int> scanReference(const std::vector<int>& v, const std::vector<bool>& start,
                               const std::vector<bool>& takesPart, std::vector<int> out,
                               ScanKind kind) {
  int running = 0;
  bool first = true;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!takesPart[i]) continue;
    if (start[i] || first) running = 0;
    first = false;
    out[i] = kind == ScanKind::Inclusive ? running + v[i] : running;
    running += v[i];
  }
  return out;
}

TEST(SegmentedScan, MatchesScalarInclusiveAndExclusiveWithAMask) {
  MeshMachine m({8, 16});
  const int n = 128;
  const auto values = test::randomInts(n, -9, 9, 1);
  const auto startBits = test::randomInts(n, 0, 4, 2);
  std::vector<bool> start, all(n, true), part;
  for (int b : startBits) start.push_back(b == 0);
  const Plural<bool> cond = test::randomCondition(m, 0.7, 3);
  for (int pe = 0; pe < n; ++pe) part.push_back(cond[pe]);
  for (ScanKind kind : {ScanKind::Inclusive, ScanKind::Exclusive}) {
    Plural<int> src(m), dst(m, 77);
    Plural<bool> flags(m);
    test::load(src, values);
    for (int pe = 0; pe < n; ++pe) flags[pe] = start[pe];
    segmentedScan(m, dst, src, flags, kind);
    EXPECT_TRUE(samePerPe(m.grid(), dst, scanReference(values, start, all, std::vector<int>(n, 77), kind)));
    Plural<int> masked(m, 77);
    {
      ActiveScope scope(m, cond);
      segmentedScan(m, masked, src, flags, kind);
    }
    EXPECT_TRUE(samePerPe(m.grid(), masked, scanReference(values, start, part, std::vector<int>(n, 77), kind)));
  }
}

TEST(SegmentedScan, ListsScanInPeThenSlotOrder) {
  MeshMachine m({4, 4});
  PeArray<int> src(m, "src"), dst(m, "dst");
  PeArray<bool> flags(m, "flags");
  std::vector<int> seq;
  std::vector<bool> start;
  const auto lengths = test::randomInts(16, 0, 5, 6);
  const auto values = test::randomInts(100, 1, 9, 7);
  int next = 0;
  for (int pe = 0; pe < 16; ++pe)
    for (int i = 0; i < lengths[pe]; ++i, ++next) {
      src.push(pe, values[next]);
      flags.push(pe, values[next] == 5);
      seq.push_back(values[next]);
      start.push_back(values[next] == 5);
    }
  segmentedScan(m, dst, src, flags, ScanKind::Inclusive);
  const auto expected =
      scanReference(seq, start, std::vector<bool>(seq.size(), true), std::vector<int>(seq.size()), ScanKind::Inclusive);
  next = 0;
  for (int pe = 0; pe < 16; ++pe) {
    ASSERT_EQ(dst.count(pe), lengths[pe]);
    for (int i = 0; i < lengths[pe]; ++i, ++next)
      ASSERT_EQ(dst.at(pe, i), expected[next]) << m.grid().name(pe) << " slot " << i;
  }
}

}  // namespace
}  // namespace radmesh::emu
