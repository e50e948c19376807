#include <gtest/gtest.h>

#include <string>

#include "parallel/mpi/mpi_session.h"

namespace radmesh::mpi {
namespace {

TEST(MpiSession, RanksAreTheWorld) {
  int size = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  int sum = 0;
  const int one = 1;
  check(MPI_Allreduce(&one, &sum, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce");
  EXPECT_EQ(sum, size);
}

TEST(MpiSession, AFailedCallNamesTheRankAndTheCall) {
  int size = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const int value = 0;
  try {
    check(MPI_Send(&value, 1, MPI_INT, size + 5, 0, MPI_COMM_WORLD), "MPI_Send");
    FAIL() << "a send to a rank that does not exist must fail";
  } catch (const MpiError& e) {
    const std::string expected = "rank " + std::to_string(worldRank()) + ": MPI_Send failed: ";
    EXPECT_EQ(std::string(e.what()).substr(0, expected.size()), expected) << e.what();
  }
}

}  // namespace
}  // namespace radmesh::mpi
