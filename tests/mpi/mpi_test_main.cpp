// The MPI tests' main: every rank runs every test (SPMD); a test fails the run if it fails on any
// rank, since mpirun returns non-zero when a rank does.
#include <gtest/gtest.h>

#include "parallel/mpi/mpi_session.h"

int main(int argc, char** argv) {
  radmesh::mpi::Session session(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  // Rank 0 alone prints progress; failures print on the rank that failed.
  if (session.rank() != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  return RUN_ALL_TESTS();
}
