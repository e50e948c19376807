#pragma once
// Form-factor reuse (the paper's section 1.6.2): rows of shooters that may shoot again, kept
// within a memory budget, least recently used dropped first.
#include <cstddef>
#include <list>
#include <unordered_map>
#include <vector>

#include "solver/formfactors/form_factor_row.h"

namespace radmesh {

class FormFactorCache {
 public:
  explicit FormFactorCache(std::size_t budgetBytes) : budgetBytes_(budgetBytes) {}

  // The cached row of a shooter (now the most recently used), or null.
  const FormFactorRow* find(int shooter);
  // Keeps a copy, dropping the least recently used rows to stay within budget; a row larger than
  // the whole budget is not kept.
  void insert(const FormFactorRow& row);

  // After the receivers were renumbered (adaptive subdivision split some): newIndex gives each old
  // receiver's new index, or -1 for one that split. Rows that reach a split receiver are dropped
  // (their light on its children is unknown); the others are renumbered, in the same order of use.
  void renumberReceivers(const std::vector<int>& newIndex);
  // Drops a shooter's row, if cached.
  void erase(int shooter);

  // The cached rows, most recently used first: inserted back to front into an empty cache of the
  // same budget, they make it again as it was.
  std::vector<FormFactorRow> contents() const { return {order_.begin(), order_.end()}; }

  std::size_t bytes() const { return bytes_; }
  std::size_t rows() const { return order_.size(); }

 private:
  std::size_t budgetBytes_;
  std::size_t bytes_ = 0;
  std::list<FormFactorRow> order_;  // most recently used first
  std::unordered_map<int, std::list<FormFactorRow>::iterator> byShooter_;
};

}  // namespace radmesh
