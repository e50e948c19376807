#pragma once
// A plural value: one T on every PE of a machine, indexed by global PE id; this process stores its
// block's values (MeshMachine::block), row-major and contiguous so SIMD steps are tight loops. It reserves kWireBytes<T> of each PE's local memory for as long as it lives.
// Host access through operator[] is the front end reading or writing PE memory (not charged).
#include <algorithm>
#include <memory>
#include <span>
#include <string_view>

#include "emulator/mesh_machine.h"
#include "emulator/wire_size.h"

namespace radmesh::emu {

template <class T>
class Plural {
 public:
  explicit Plural(MeshMachine& machine, const T& init = T{}, std::string_view label = "plural")
      : machine_(&machine), values_(new T[machine.blockSize()]) {
    machine.memory().reserve(kWireBytes<T>, label);
    std::fill_n(values_.get(), machine.blockSize(), init);
  }
  Plural(const Plural& other) : machine_(other.machine_), values_(new T[other.blockSize()]) {
    machine_->memory().reserve(kWireBytes<T>, "copy of a plural");
    std::copy_n(other.values_.get(), other.blockSize(), values_.get());
  }
  Plural(Plural&& other) noexcept
      : machine_(other.machine_), values_(std::move(other.values_)) {}
  Plural& operator=(const Plural& other) {
    if (this != &other) {
      requireSameMachine(*machine_, other.machine(), "Plural assignment");
      std::copy_n(other.values_.get(), other.blockSize(), values_.get());
    }
    return *this;
  }
  Plural& operator=(Plural&& other) noexcept {
    if (this != &other) {
      if (values_) machine_->memory().release(kWireBytes<T>);
      machine_ = other.machine_;
      values_ = std::move(other.values_);
    }
    return *this;
  }
  ~Plural() {
    if (values_) machine_->memory().release(kWireBytes<T>);
  }

  T& operator[](int pe) { return values_[machine_->local(pe)]; }  // pe must be in the block
  const T& operator[](int pe) const { return values_[machine_->local(pe)]; }
  // The block's values, by local index.
  std::span<T> values() { return {values_.get(), static_cast<std::size_t>(blockSize())}; }
  std::span<const T> values() const { return {values_.get(), static_cast<std::size_t>(blockSize())}; }
  T* data() { return values_.get(); }
  const T* data() const { return values_.get(); }
  int size() const { return machine_->size(); }  // PEs of the machine
  int blockSize() const { return machine_->blockSize(); }
  MeshMachine& machine() const { return *machine_; }

 private:
  MeshMachine* machine_;
  std::unique_ptr<T[]> values_;
};

// SIMD `if (condition) {...} else {...}` as a scope: the constructor narrows the active set to
// the PEs where condition holds, elseBranch() flips to the others, the destructor restores.
class ActiveScope {
 public:
  ActiveScope(MeshMachine& machine, const Plural<bool>& condition) : machine_(machine) {
    machine.pushActive(condition.values());
  }
  ~ActiveScope() { machine_.popActive(); }
  ActiveScope(const ActiveScope&) = delete;
  ActiveScope& operator=(const ActiveScope&) = delete;
  void elseBranch() { machine_.flipActive(); }

 private:
  MeshMachine& machine_;
};

}  // namespace radmesh::emu
