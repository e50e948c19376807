#include "solver/projection/plane_mapping.h"

#include <algorithm>
#include <cmath>

#include "solver/scene/scene_error.h"

namespace radmesh {

const char* toString(MappingKind kind) {
  switch (kind) {
    case MappingKind::Hierarchical: return "hierarchical";
    case MappingKind::CutAndStack: return "cut-and-stack";
    case MappingKind::Adaptive: return "adaptive";
  }
  return "?";
}

MappingKind parseMapping(const std::string& text) {
  for (MappingKind k : {MappingKind::Hierarchical, MappingKind::CutAndStack, MappingKind::Adaptive})
    if (text == toString(k)) return k;
  throw OptionError("--mapping '" + text + "' is not a mapping: use hierarchical, cut-and-stack or adaptive");
}

AxisMapping::AxisMapping(std::vector<int> peOf, int pes, bool cyclic)
    : peOf_(std::move(peOf)), first_(pes + 1, 0), cyclic_(cyclic) {
  for (int pe : peOf_) ++first_[pe + 1];
  for (int pe = 0; pe < pes; ++pe) first_[pe + 1] += first_[pe];
  order_.resize(peOf_.size());
  std::vector<int> next(first_.begin(), first_.end() - 1);
  for (int p = 0; p < pixels(); ++p) order_[next[peOf_[p]]++] = p;
}

AxisMapping AxisMapping::blocks(int pixels, int pes) {
  std::vector<int> peOf(pixels);
  for (int p = 0; p < pixels; ++p)
    peOf[p] = static_cast<int>(static_cast<long long>(p) * pes / pixels);
  return AxisMapping(std::move(peOf), pes, false);
}

AxisMapping AxisMapping::cyclic(int pixels, int pes) {
  std::vector<int> peOf(pixels);
  for (int p = 0; p < pixels; ++p) peOf[p] = p % pes;
  return AxisMapping(std::move(peOf), pes, true);
}

AxisMapping AxisMapping::fromLoads(std::span<const double> loadPerPixel, int pes) {
  const int n = static_cast<int>(loadPerPixel.size());
  // SIMD time grows with the most pixels any PE holds: with no more pixels than PEs, one pixel
  // per PE is already the best balance.
  if (n <= pes) return blocks(n, pes);
  double total = 0.0;
  for (double l : loadPerPixel) total += l;
  const double floor = total > 0.0 ? kAdaptiveLoadFloor * total / n : 1.0;
  const double padded = total + floor * n;
  // Pixel p goes to the PE whose share of the cumulative load holds p's midpoint: monotone.
  std::vector<int> peOf(n);
  double before = 0.0;
  for (int p = 0; p < n; ++p) {
    const double load = loadPerPixel[p] + floor;
    const double mid = (before + 0.5 * load) / padded;
    peOf[p] = std::min(pes - 1, static_cast<int>(mid * pes));
    before += load;
  }
  return AxisMapping(std::move(peOf), pes, false);
}

int AxisMapping::maxPixelsPerPe() const {
  int most = 0;
  for (int pe = 0; pe < pes(); ++pe) most = std::max(most, first_[pe + 1] - first_[pe]);
  return most;
}

int AxisMapping::stepsToCover(int begin, int end) const {
  if (end <= begin) return 0;
  if (cyclic_) return std::min(pes(), end - begin) - 1;
  return peOf_[end - 1] - peOf_[begin];  // monotone: the last pixel is on the farthest PE
}

PlaneMapping PlaneMapping::uniform(MappingKind kind, int resolution, int peRows, int peCols) {
  if (kind == MappingKind::CutAndStack)
    return {AxisMapping::cyclic(resolution, peCols), AxisMapping::cyclic(resolution, peRows)};
  return {AxisMapping::blocks(resolution, peCols), AxisMapping::blocks(resolution, peRows)};
}

}  // namespace radmesh
