#include "solver/formfactors/form_factor_cache.h"

#include <algorithm>
#include <utility>

namespace radmesh {

const FormFactorRow* FormFactorCache::find(int shooter) {
  const auto it = byShooter_.find(shooter);
  if (it == byShooter_.end()) return nullptr;
  order_.splice(order_.begin(), order_, it->second);
  return &*it->second;
}

void FormFactorCache::insert(const FormFactorRow& row) {
  if (byShooter_.count(row.shooter)) return;
  FormFactorRow kept = row;  // a copy holds no spare capacity
  const std::size_t need = kept.bytes();
  if (need > budgetBytes_) return;
  while (bytes_ + need > budgetBytes_) {
    bytes_ -= order_.back().bytes();
    byShooter_.erase(order_.back().shooter);
    order_.pop_back();
  }
  order_.push_front(std::move(kept));
  bytes_ += need;
  byShooter_[row.shooter] = order_.begin();
}

void FormFactorCache::renumberReceivers(const std::vector<int>& newIndex) {
  for (auto row = order_.begin(); row != order_.end();) {
    const auto gone = [&](int r) { return newIndex[r] < 0; };
    const bool split = std::any_of(row->receivers.begin(), row->receivers.end(), gone) ||
                       std::any_of(row->binShares.begin(), row->binShares.end(),
                                   [&](const FormFactorRow::BinShare& share) { return gone(share.patch); });
    if (split) {
      const int shooter = row->shooter;
      ++row;
      erase(shooter);
      continue;
    }
    for (int& r : row->receivers) r = newIndex[r];
    for (FormFactorRow::BinShare& share : row->binShares) share.patch = newIndex[share.patch];  // receivers too
    ++row;
  }
}

void FormFactorCache::erase(int shooter) {
  const auto it = byShooter_.find(shooter);
  if (it == byShooter_.end()) return;
  bytes_ -= it->second->bytes();
  order_.erase(it->second);
  byShooter_.erase(it);
}

}  // namespace radmesh
