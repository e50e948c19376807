#include "emulator/active_mask.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace radmesh::emu {

ActiveMask::ActiveMask(int size) : size_(size) {
  stack_.emplace_back(static_cast<std::size_t>(size), std::uint8_t{1});
  counts_.push_back(size);
}

void ActiveMask::pushFlags(std::vector<std::uint8_t> flags) {
  counts_.push_back(static_cast<int>(std::count(flags.begin(), flags.end(), std::uint8_t{1})));
  stack_.push_back(std::move(flags));
}

void ActiveMask::push(std::span<const bool> condition) {
  if (static_cast<int>(condition.size()) != size_)
    throw std::invalid_argument("ActiveMask::push: condition has " +
                                std::to_string(condition.size()) + " values for " +
                                std::to_string(size_) + " PEs");
  const auto& current = top();
  std::vector<std::uint8_t> next(current.size());
  for (int pe = 0; pe < size_; ++pe) next[pe] = current[pe] & (condition[pe] ? 1 : 0);
  pushFlags(std::move(next));
}

void ActiveMask::flip() {
  if (depth() == 0) throw std::logic_error("ActiveMask::flip: no condition was pushed");
  const auto& outer = stack_[stack_.size() - 2];
  auto& current = stack_.back();
  int count = 0;
  for (int pe = 0; pe < size_; ++pe) {
    current[pe] = outer[pe] & (current[pe] ^ 1);
    count += current[pe];
  }
  counts_.back() = count;
}

void ActiveMask::pop() {
  if (depth() == 0) throw std::logic_error("ActiveMask::pop: no condition was pushed");
  stack_.pop_back();
  counts_.pop_back();
}

}  // namespace radmesh::emu
