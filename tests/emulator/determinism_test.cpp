// The same mesh program gives the same bits and the same counts whatever the host thread count.
#include <gtest/gtest.h>

#include <cmath>

#include "emulator/mesh_sort.h"
#include "emulator/reduce.h"
#include "emulator/router.h"
#include "emulator/scan.h"
#include "emulator/xnet.h"
#include "tests/emulator/plural_compare.h"

namespace radmesh::emu {
namespace {

struct Outcome {
  std::vector<double> values;
  std::vector<int> keys;
  double sum = 0.0;
  Located<double> best;
  CostCounts costs;
};

Outcome runProgram(int threads) {
  MeshMachine m({32, 32, 16 * 1024, threads});
  Plural<double> x(m), y(m);
  Plural<int> key(m), to(m);
  // Heavy declared work, so compute() really runs on the pool when threads > 1.
  m.compute({500.0, 0.0}, [&](int pe) {
    double s = 0.0;
    for (int i = 1; i <= 200; ++i) s += std::sin(pe * 0.01 * i) / i;
    x[pe] = s;
    key[pe] = static_cast<int>(std::fabs(s) * 1000) % 97;
    to[pe] = (pe * 37) % 64;
  });
  xnetShift(m, y, x, Direction::SE, 3);
  routerSend(m, y, x, to, Combine::Add);
  Plural<bool> starts(m);
  for (int pe = 0; pe < m.size(); ++pe) starts[pe] = pe % 5 == 0;
  segmentedScan(m, x, y, starts, ScanKind::Inclusive);
  sortPairs(m, key, x);
  Outcome o;
  o.sum = reduceAdd(m, x);
  o.best = reduceMax(m, x);
  o.values.assign(x.data(), x.data() + m.size());
  o.keys.assign(key.data(), key.data() + m.size());
  o.costs = m.costs();
  return o;
}

TEST(Determinism, OneAndTwoThreadsGiveIdenticalBitsAndCounts) {
  const Outcome one = runProgram(1);
  const Outcome two = runProgram(2);
  for (std::size_t pe = 0; pe < one.values.size(); ++pe) {
    ASSERT_EQ(one.values[pe], two.values[pe]) << "first difference at PE " << pe;
    ASSERT_EQ(one.keys[pe], two.keys[pe]) << "first difference at PE " << pe;
  }
  EXPECT_EQ(one.sum, two.sum);
  EXPECT_EQ(one.best.pe, two.best.pe);
  EXPECT_EQ(one.costs.summary(), two.costs.summary());
}

}  // namespace
}  // namespace radmesh::emu
