#pragma once
// Comparing emulator results with plain scalar references: the first PE that differs is named.
#include <gtest/gtest.h>

#include <random>
#include <sstream>
#include <vector>

#include "emulator/plural.h"

namespace radmesh::emu::test {

// Success, or a failure naming the first PE (row, col) whose value differs and both values.
template <class T>
::testing::AssertionResult samePerPe(const PeGrid& grid, const Plural<T>& actual,
                                     const std::vector<T>& expected) {
  for (int pe = 0; pe < grid.size(); ++pe)
    if (!(actual[pe] == expected[pe])) {
      std::ostringstream out;
      out << "first difference at " << grid.name(pe) << ": got " << actual[pe] << ", expected "
          << expected[pe];
      return ::testing::AssertionFailure() << out.str();
    }
  return ::testing::AssertionSuccess();
}

template <class T>
void load(Plural<T>& plural, const std::vector<T>& values) {
  for (int pe = 0; pe < plural.size(); ++pe) plural[pe] = values[pe];
}

inline std::vector<int> randomInts(int n, int lo, int hi, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> pick(lo, hi);
  std::vector<int> v(n);
  for (int& x : v) x = pick(rng);
  return v;
}

// A condition true on roughly `fraction` of the PEs, as Plural<bool>.
inline Plural<bool> randomCondition(MeshMachine& machine, double fraction, unsigned seed) {
  std::mt19937 rng(seed);
  std::bernoulli_distribution pick(fraction);
  Plural<bool> c(machine, false, "condition");
  for (int pe = 0; pe < machine.size(); ++pe) c[pe] = pick(rng);
  return c;
}

}  // namespace radmesh::emu::test
