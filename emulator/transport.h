#pragma once
// How the processes of a distributed mesh machine talk (the MPI transport: emulator/mpi/).
//
// Design: the emulated machine is the same whatever the processes; a process holds one block of
// PEs (pe_block.h) and the operations (xnet.h, router.h, reduce.h, scan.h, mesh_sort.h) move what
// crosses a block edge through this interface, in bytes, so that emulator/ needs no MPI. A machine
// without a transport is one process holding the whole torus and runs the operations as it
// always has (no exchange to emulate); with one, even on one rank, every operation takes its
// distributed path. What the transport moves is counted per operation class (the host's traffic,
// beside the emulated MP-1's CostCounts, which stay those of the one-process machine).
#include <cstddef>
#include <cstdint>
#include <array>
#include <functional>
#include <span>
#include <vector>

#include "emulator/pe_block.h"

namespace radmesh::emu {

using Bytes = std::vector<std::byte>;

// The operation class a transfer belongs to (as in CostCounts), or the front end reading PE
// memory (front_end.h), which the MP-1 does over its own bus and CostCounts leave out.
enum class Channel { Xnet, Router, Reduce, Scan, Sort, FrontEnd };
inline constexpr int kChannels = 6;
const char* toString(Channel channel);

// Point-to-point messages and payload bytes this rank sent to other ranks (a transfer to itself is
// a copy, not counted); a collective counts one message per peer its data goes to.
struct Traffic {
  std::int64_t messages = 0;
  std::int64_t bytes = 0;
};

class Transport {
 public:
  // Combines `in` into `inout` (both one value of the reduced type). For allReduce it must be
  // commutative and associative, as the values arrive in any order; along a line of ranks only
  // associative, `in` being the part of the earlier ranks.
  using Combiner = std::function<void(const std::byte* in, std::byte* inout)>;

  virtual ~Transport() = default;
  virtual RankGrid rankGrid() const = 0;
  virtual int rank() const = 0;
  virtual int rankRow() const = 0;
  virtual int rankCol() const = 0;
  virtual int rankAt(int rankRow, int rankCol) const = 0;  // wraps around (periodic)

  // Sends `data` to the rank `displacement` steps along the rank grid's `axis` (0: down the rank
  // rows, 1: along the rank cols) and returns what the rank as far the other way sent.
  virtual Bytes shift(Channel channel, int axis, int displacement, std::span<const std::byte> data) = 0;
  // Sends data to `partner` and returns what it sent (a pairwise exchange).
  virtual Bytes exchange(Channel channel, int partner, std::span<const std::byte> data) = 0;
  // toRank[r] goes to rank r; returns what each rank sent here.
  virtual std::vector<Bytes> allToAll(Channel channel, const std::vector<Bytes>& toRank) = 0;
  // Every rank's data, by rank.
  virtual std::vector<Bytes> allGather(Channel channel, std::span<const std::byte> data) = 0;
  // Replaces value by the combination of every rank's value.
  virtual void allReduce(Channel channel, std::span<std::byte> value, const Combiner& combine) = 0;
  // Along a line of the rank grid (`axis` 0: the ranks of this rank's column, in rank-row order;
  // 1: those of its row, in rank-column order), combining in that order: value becomes the
  // combination of the line's values (allReduceAlong), or of the values of the ranks before this
  // one (exclusiveScanAlong, which returns false, value unspecified, on the line's first rank).
  virtual void allReduceAlong(Channel channel, int axis, std::span<std::byte> value, const Combiner& combine) = 0;
  virtual bool exclusiveScanAlong(Channel channel, int axis, std::span<std::byte> value, const Combiner& combine) = 0;

  const Traffic& traffic(Channel channel) const { return traffic_[static_cast<int>(channel)]; }
  void resetTraffic() { traffic_ = {}; }

 protected:
  void count(Channel channel, std::int64_t messages, std::int64_t bytes) {
    traffic_[static_cast<int>(channel)].messages += messages;
    traffic_[static_cast<int>(channel)].bytes += bytes;
  }

 private:
  std::array<Traffic, kChannels> traffic_{};
};

}  // namespace radmesh::emu
