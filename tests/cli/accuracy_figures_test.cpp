#include <gtest/gtest.h>

#include "cli/bench_accuracy_figures.h"

namespace radmesh::cli::accuracy_sweep {
namespace {

// The front holds the points no other beats in both time and error, in order of time; a point
// equalled in error by a faster one, or beaten in both, is off it.
TEST(AccuracyFigures, TheParetoFrontIsThePointsNoneBeatsInOrderOfTime) {
  const std::vector<std::pair<double, double>> points = {
      {5.0, 4.0},   // 0: the most accurate
      {1.0, 20.0},  // 1: the fastest
      {2.0, 9.0},   // 2: on the front
      {3.0, 9.0},   // 3: as accurate as 2, slower
      {4.0, 12.0},  // 4: beaten by 2 in both
      {2.5, 6.0},   // 5: on the front
  };
  EXPECT_EQ(paretoIndices(points), (std::vector<size_t>{1, 2, 5, 0}));
  EXPECT_TRUE(paretoIndices({}).empty());
}

}  // namespace
}  // namespace radmesh::cli::accuracy_sweep
