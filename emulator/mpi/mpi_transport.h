#pragma once
// The mesh machine's processes over MPI: the ranks of a communicator form a periodic Cartesian
// grid (MPI_Dims_create, MPI_Cart_create with periods 1, 1), one block of the PE torus each.
// Block edges move with MPI_Cart_shift and MPI_Sendrecv, router messages with MPI_Alltoallv,
// reductions with MPI_Allreduce, gathers with MPI_Allgatherv; combinations along a rank row or
// column (an integer scan's summaries) with MPI_Allreduce and MPI_Exscan of a non-commutative
// operation on a communicator per line. Every failed call throws radmesh::mpi::MpiError naming
// the rank and the call.
#include <mpi.h>

#include "emulator/transport.h"

namespace radmesh::emu {

class MpiTransport final : public Transport {
 public:
  // Every rank of `comm` takes part (collectively, as every call here).
  explicit MpiTransport(MPI_Comm comm = MPI_COMM_WORLD);
  ~MpiTransport() override;
  MpiTransport(const MpiTransport&) = delete;
  MpiTransport& operator=(const MpiTransport&) = delete;

  RankGrid rankGrid() const override { return {dims_[0], dims_[1]}; }
  int rank() const override { return rank_; }
  int rankRow() const override { return coords_[0]; }
  int rankCol() const override { return coords_[1]; }
  int rankAt(int rankRow, int rankCol) const override;

  Bytes shift(Channel channel, int axis, int displacement, std::span<const std::byte> data) override;
  Bytes exchange(Channel channel, int partner, std::span<const std::byte> data) override;
  std::vector<Bytes> allToAll(Channel channel, const std::vector<Bytes>& toRank) override;
  std::vector<Bytes> allGather(Channel channel, std::span<const std::byte> data) override;
  void allReduce(Channel channel, std::span<std::byte> value, const Combiner& combine) override;
  void allReduceAlong(Channel channel, int axis, std::span<std::byte> value, const Combiner& combine) override;
  bool exclusiveScanAlong(Channel channel, int axis, std::span<std::byte> value, const Combiner& combine) override;

 private:
  Bytes sendReceive(Channel channel, int to, int from, std::span<const std::byte> data);

  MPI_Comm cart_ = MPI_COMM_NULL;
  MPI_Comm lines_[2] = {MPI_COMM_NULL, MPI_COMM_NULL};  // this rank's column and row, as `axis`
  int rank_ = 0;
  int ranks_ = 1;
  int dims_[2] = {0, 0};
  int coords_[2] = {0, 0};
};

}  // namespace radmesh::emu
