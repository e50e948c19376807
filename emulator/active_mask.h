#pragma once
// The set of active PEs, as a SIMD `if` leaves it: push a condition to narrow the set, flip it for
// the `else` branch, pop to restore. Operations act on active PEs only (see each operation).
#include <cstdint>
#include <span>
#include <vector>

namespace radmesh::emu {

class ActiveMask {
 public:
  explicit ActiveMask(int size);

  bool active(int pe) const { return top()[pe] != 0; }
  const std::uint8_t* flags() const { return top().data(); }
  bool allActive() const { return counts_.back() == size_; }
  int activeCount() const { return counts_.back(); }
  int depth() const { return static_cast<int>(stack_.size()) - 1; }

  void push(std::span<const bool> condition);  // active := active and condition
  void flip();  // active := enclosing active and not (current condition): the `else` branch
  void pop();   // throws std::logic_error when nothing was pushed

 private:
  const std::vector<std::uint8_t>& top() const { return stack_.back(); }
  void pushFlags(std::vector<std::uint8_t> flags);

  int size_;
  std::vector<std::vector<std::uint8_t>> stack_;
  std::vector<int> counts_;
};

}  // namespace radmesh::emu
