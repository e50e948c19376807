#include "emulator/mpi/mpi_transport.h"

#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "parallel/mpi/mpi_session.h"

namespace radmesh::emu {

namespace {
using ::radmesh::mpi::check;
constexpr int kTag = 14;

// MPI_Op functions take no context: the combiner of the reduction in progress (one at a time,
// on the thread that made the MPI session).
thread_local const Transport::Combiner* currentCombiner = nullptr;
thread_local std::size_t currentSize = 0;
void combineValues(void* in, void* inout, int* count, MPI_Datatype*) {
  for (int i = 0; i < *count; ++i)
    (*currentCombiner)(static_cast<const std::byte*>(in) + i * currentSize,
                       static_cast<std::byte*>(inout) + i * currentSize);
}

int size(std::size_t bytes) {
  if (bytes > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::length_error("a mesh transfer of " + std::to_string(bytes) +
                            " bytes exceeds one MPI message; use more ranks");
  return static_cast<int>(bytes);
}

// Runs collective(type, op) on one value of `bytes` with `combine` as the operation (MPI keeps
// rank order for a non-commutative one); returns the collective's code.
template <class Collective>
int withCombiner(std::size_t bytes, const Transport::Combiner& combine, bool commutative, Collective collective) {
  MPI_Datatype type;
  check(MPI_Type_contiguous(size(bytes), MPI_BYTE, &type), "MPI_Type_contiguous");
  check(MPI_Type_commit(&type), "MPI_Type_commit");
  MPI_Op op;
  check(MPI_Op_create(&combineValues, commutative ? 1 : 0, &op), "MPI_Op_create");
  currentCombiner = &combine;
  currentSize = bytes;
  const int code = collective(type, op);
  currentCombiner = nullptr;
  MPI_Op_free(&op);
  MPI_Type_free(&type);
  return code;
}
}  // namespace

MpiTransport::MpiTransport(MPI_Comm comm) {
  check(MPI_Comm_size(comm, &ranks_), "MPI_Comm_size");
  check(MPI_Dims_create(ranks_, 2, dims_), "MPI_Dims_create");
  const int periods[2] = {1, 1};
  check(MPI_Cart_create(comm, 2, dims_, periods, 0, &cart_), "MPI_Cart_create");
  MPI_Comm_set_errhandler(cart_, MPI_ERRORS_RETURN);
  check(MPI_Comm_rank(cart_, &rank_), "MPI_Comm_rank");
  check(MPI_Cart_coords(cart_, rank_, 2, coords_), "MPI_Cart_coords");
  // A line's ranks keyed by their coordinate along it, so that its order is the rank grid's.
  for (int axis : {0, 1}) {
    check(MPI_Comm_split(cart_, coords_[1 - axis], coords_[axis], &lines_[axis]), "MPI_Comm_split");
    MPI_Comm_set_errhandler(lines_[axis], MPI_ERRORS_RETURN);
  }
}

MpiTransport::~MpiTransport() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (finalized) return;
  for (MPI_Comm& line : lines_)
    if (line != MPI_COMM_NULL) MPI_Comm_free(&line);
  if (cart_ != MPI_COMM_NULL) MPI_Comm_free(&cart_);
}

int MpiTransport::rankAt(int rankRow, int rankCol) const {
  const int coords[2] = {((rankRow % dims_[0]) + dims_[0]) % dims_[0], ((rankCol % dims_[1]) + dims_[1]) % dims_[1]};
  int rank = 0;
  check(MPI_Cart_rank(cart_, coords, &rank), "MPI_Cart_rank");
  return rank;
}

Bytes MpiTransport::sendReceive(Channel channel, int to, int from, std::span<const std::byte> data) {
  if (to == rank_ && from == rank_) return Bytes(data.begin(), data.end());
  long long sending = static_cast<long long>(data.size()), receiving = 0;
  check(MPI_Sendrecv(&sending, 1, MPI_LONG_LONG, to, kTag, &receiving, 1, MPI_LONG_LONG, from, kTag, cart_,
                     MPI_STATUS_IGNORE),
        "MPI_Sendrecv");
  Bytes received(static_cast<std::size_t>(receiving));
  check(MPI_Sendrecv(data.data(), size(data.size()), MPI_BYTE, to, kTag, received.data(),
                     size(received.size()), MPI_BYTE, from, kTag, cart_, MPI_STATUS_IGNORE),
        "MPI_Sendrecv");
  count(channel, 2, static_cast<std::int64_t>(sizeof sending + data.size()));
  return received;
}

Bytes MpiTransport::shift(Channel channel, int axis, int displacement, std::span<const std::byte> data) {
  int from = 0, to = 0;
  check(MPI_Cart_shift(cart_, axis, displacement, &from, &to), "MPI_Cart_shift");
  return sendReceive(channel, to, from, data);
}

Bytes MpiTransport::exchange(Channel channel, int partner, std::span<const std::byte> data) {
  return sendReceive(channel, partner, partner, data);
}

std::vector<Bytes> MpiTransport::allToAll(Channel channel, const std::vector<Bytes>& toRank) {
  std::vector<int> sendCounts(ranks_), receiveCounts(ranks_), sendAt(ranks_), receiveAt(ranks_);
  Bytes sending;
  for (int r = 0; r < ranks_; ++r) {
    sendAt[r] = size(sending.size());
    sendCounts[r] = size(toRank[r].size());
    sending.insert(sending.end(), toRank[r].begin(), toRank[r].end());
  }
  check(MPI_Alltoall(sendCounts.data(), 1, MPI_INT, receiveCounts.data(), 1, MPI_INT, cart_), "MPI_Alltoall");
  std::exclusive_scan(receiveCounts.begin(), receiveCounts.end(), receiveAt.begin(), 0);
  Bytes receiving(static_cast<std::size_t>(receiveAt.back()) + receiveCounts.back());
  check(MPI_Alltoallv(sending.data(), sendCounts.data(), sendAt.data(), MPI_BYTE, receiving.data(),
                      receiveCounts.data(), receiveAt.data(), MPI_BYTE, cart_),
        "MPI_Alltoallv");
  std::int64_t messages = ranks_ - 1, bytes = static_cast<std::int64_t>(sizeof(int)) * (ranks_ - 1);
  for (int r = 0; r < ranks_; ++r)
    if (r != rank_ && sendCounts[r] > 0) ++messages, bytes += sendCounts[r];
  count(channel, messages, bytes);
  std::vector<Bytes> received(ranks_);
  for (int r = 0; r < ranks_; ++r)
    received[r].assign(receiving.begin() + receiveAt[r], receiving.begin() + receiveAt[r] + receiveCounts[r]);
  return received;
}

std::vector<Bytes> MpiTransport::allGather(Channel channel, std::span<const std::byte> data) {
  const int mine = size(data.size());
  std::vector<int> counts(ranks_), at(ranks_);
  check(MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, cart_), "MPI_Allgather");
  std::exclusive_scan(counts.begin(), counts.end(), at.begin(), 0);
  Bytes all(static_cast<std::size_t>(at.back()) + counts.back());
  check(MPI_Allgatherv(data.data(), mine, MPI_BYTE, all.data(), counts.data(), at.data(), MPI_BYTE, cart_),
        "MPI_Allgatherv");
  count(channel, 2 * (ranks_ - 1), static_cast<std::int64_t>(ranks_ - 1) * (sizeof(int) + data.size()));
  std::vector<Bytes> byRank(ranks_);
  for (int r = 0; r < ranks_; ++r) byRank[r].assign(all.begin() + at[r], all.begin() + at[r] + counts[r]);
  return byRank;
}

void MpiTransport::allReduce(Channel channel, std::span<std::byte> value, const Combiner& combine) {
  if (ranks_ == 1) return;
  check(withCombiner(value.size(), combine, true,
                     [&](MPI_Datatype type, MPI_Op op) {
                       return MPI_Allreduce(MPI_IN_PLACE, value.data(), 1, type, op, cart_);
                     }),
        "MPI_Allreduce");
  count(channel, ranks_ - 1, static_cast<std::int64_t>(ranks_ - 1) * value.size());
}

void MpiTransport::allReduceAlong(Channel channel, int axis, std::span<std::byte> value, const Combiner& combine) {
  const int peers = dims_[axis] - 1;
  if (peers == 0) return;
  check(withCombiner(value.size(), combine, false,
                     [&](MPI_Datatype type, MPI_Op op) {
                       return MPI_Allreduce(MPI_IN_PLACE, value.data(), 1, type, op, lines_[axis]);
                     }),
        "MPI_Allreduce");
  count(channel, peers, static_cast<std::int64_t>(peers) * value.size());
}

bool MpiTransport::exclusiveScanAlong(Channel channel, int axis, std::span<std::byte> value, const Combiner& combine) {
  if (dims_[axis] == 1) return false;
  check(withCombiner(value.size(), combine, false,
                     [&](MPI_Datatype type, MPI_Op op) {
                       return MPI_Exscan(MPI_IN_PLACE, value.data(), 1, type, op, lines_[axis]);
                     }),
        "MPI_Exscan");
  const int later = dims_[axis] - 1 - coords_[axis];  // the ranks this one's value goes into
  count(channel, later, static_cast<std::int64_t>(later) * value.size());
  return coords_[axis] > 0;
}

}  // namespace radmesh::emu
