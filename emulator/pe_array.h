#pragma once
// A per-PE local array: each PE holds a list of T (an item buffer, a queue of descriptions). As a
// plural array on a SIMD machine, every PE reserves room for the longest list any PE has had, so
// the memory charged is that length x kWireBytes<T> on every PE; growing past the budget throws,
// naming the PE whose list forced it. Lists are indexed by global PE id; this process stores its
// block's lists (MeshMachine::block).
#include <algorithm>
#include <cstring>
#include <memory>
#include <new>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "emulator/distributed.h"
#include "emulator/mesh_machine.h"
#include "emulator/wire_size.h"

namespace radmesh::emu {

template <class T>
class PeArray {
  // Host storage is raw memory holding only what the lists hold: a grown reservation touches no
  // page until a PE's list reaches it (value-initialising it cost 0.2 s a regrow of descriptions).
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                "PE memory holds plain records");

 public:
  // Empty lists on every PE.
  explicit PeArray(MeshMachine& machine, std::string label = "local array")
      : machine_(&machine), label_(std::move(label)), counts_(machine.blockSize(), 0) {}
  // `length` copies of init on every PE (a plural array of fixed length).
  PeArray(MeshMachine& machine, int length, const T& init, std::string label = "local array")
      : PeArray(machine, std::move(label)) {
    reserve(length);
    std::fill_n(data_.get(), stride_ * counts_.size(), init);
    std::fill(counts_.begin(), counts_.end(), length);
  }
  PeArray(const PeArray&) = delete;
  PeArray& operator=(const PeArray&) = delete;
  ~PeArray() { machine_->memory().release(chargedBytes()); }

  int count(int pe) const { return counts_[machine_->local(pe)]; }
  T& at(int pe, int i) { return data_[offset(pe) + i]; }
  const T& at(int pe, int i) const { return data_[offset(pe) + i]; }
  std::span<T> list(int pe) { return {data_.get() + offset(pe), listSize(pe)}; }
  std::span<const T> list(int pe) const { return {data_.get() + offset(pe), listSize(pe)}; }
  // The longest list on any PE; distributed, a reduction over the ranks (every rank asks together).
  int maxCount() const {
    const int longest = *std::max_element(counts_.begin(), counts_.end());
    if (!machine_->distributed()) return longest;
    return detail::allReduce(*machine_, Channel::Reduce, longest, [](int in, int& inout) { inout = std::max(inout, in); });
  }
  int reservedLength() const { return charged_; }  // per PE, in elements
  MeshMachine& machine() const { return *machine_; }
  const std::string& label() const { return label_; }

  // Makes room for `length` elements on every PE; `pe` names the PE that needs it. Serial only.
  void reserve(int length, int pe = 0) {
    if (length <= charged_) return;
    requireSerial("reserve");
    machine_->memory().reserve(static_cast<std::int64_t>(length - charged_) * kWireBytes<T>, label_, pe);
    charged_ = length;
    if (length > stride_) regrow(std::max(length, 2 * stride_));
  }
  // reserve() for the longest `length` any process has (each names its PE that needs it), so that
  // every process reserves alike; collective when distributed.
  void reserveAcross(int length, int pe) {
    const detail::MaxAt need = detail::allMaxAt(*machine_, Channel::Reduce, {length, pe});
    reserve(static_cast<int>(need.value), need.pe);
  }
  // Appends to one PE's list (front-end or serial code: may grow every PE's reservation).
  void push(int pe, const T& value) {
    int& count = counts_[machine_->local(pe)];
    if (count == charged_) reserve(count + 1, pe);
    at(pe, count++) = value;
  }
  // Appends within the reserved length only; safe inside MeshMachine::compute.
  void pushReserved(int pe, const T& value) {
    int& count = counts_[machine_->local(pe)];
    if (count == charged_)
      throw std::logic_error("PeArray '" + label_ + "': " + machine_->grid().name(pe) +
                             " exceeds its reserved length " + std::to_string(charged_) +
                             "; reserve() before the parallel step");
    at(pe, count++) = value;
  }
  void truncate(int pe, int count) { counts_[machine_->local(pe)] = std::min(this->count(pe), count); }
  void clear(int pe) { counts_[machine_->local(pe)] = 0; }
  void clearAll() { std::fill(counts_.begin(), counts_.end(), 0); }  // the reservation stays
  // Empties every list and gives the reserved memory back (another phase reuses it). Serial only.
  void releaseAll() {
    requireSerial("releaseAll");
    clearAll();
    machine_->memory().release(chargedBytes());
    charged_ = 0;
  }

 private:
  std::size_t offset(int pe) const { return static_cast<std::size_t>(machine_->local(pe)) * stride_; }
  std::size_t listSize(int pe) const { return static_cast<std::size_t>(count(pe)); }
  std::int64_t chargedBytes() const { return static_cast<std::int64_t>(charged_) * kWireBytes<T>; }
  void requireSerial(const char* what) const {
    if (machine_->inParallelRegion())
      throw std::logic_error(std::string("PeArray::") + what + " of '" + label_ +
                             "' inside a parallel compute(); reserve before it");
  }
  struct FreeRaw {
    void operator()(T* p) const { ::operator delete(p, std::align_val_t(alignof(T))); }
  };
  void regrow(int stride) {
    // Raw storage rather than std::vector, so that PeArray<bool> holds real bools.
    const std::size_t bytes = static_cast<std::size_t>(stride) * counts_.size() * sizeof(T);
    std::unique_ptr<T[], FreeRaw> grown(static_cast<T*>(::operator new(bytes, std::align_val_t(alignof(T)))));
    for (std::size_t pe = 0; pe < counts_.size(); ++pe)
      if (counts_[pe] > 0) std::memcpy(grown.get() + pe * stride, data_.get() + pe * stride_, counts_[pe] * sizeof(T));
    data_ = std::move(grown);
    stride_ = stride;
  }

  MeshMachine* machine_;
  std::string label_;
  std::vector<int> counts_;
  std::unique_ptr<T[], FreeRaw> data_;
  int stride_ = 0;   // host storage per PE (grows geometrically)
  int charged_ = 0;  // emulated reservation per PE (grows to exactly the longest list)
};

}  // namespace radmesh::emu
