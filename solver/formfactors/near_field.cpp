#include "solver/formfactors/near_field.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "solver/formfactors/analytic_form_factor.h"
#include "solver/meshing/elements.h"
#include "solver/projection/projection.h"

namespace radmesh {

namespace {

double diameter(const Patch& p) {
  return std::sqrt(squaredDiameter({p.vertices.data(), static_cast<size_t>(p.vertexCount)}));
}

constexpr double kRounding = 1e-9;  // of a patch's size: a vertex this close to a plane is on it

// Every vertex of `patch` on or in front of the plane of `of` (to rounding at size `scale`).
bool whollyInFront(const Patch& patch, const Patch& of, double scale) {
  for (int k = 0; k < patch.vertexCount; ++k)
    if (glm::dot(patch.vertices[k] - of.centroid, of.normal) < -kRounding * scale) return false;
  return true;
}

// How far the nearest vertex of `patch` lies in front of the plane of `of` (negative: behind).
double distanceInFront(const Patch& patch, const Patch& of) {
  double nearest = std::numeric_limits<double>::infinity();
  for (int k = 0; k < patch.vertexCount; ++k)
    nearest = std::min(nearest, glm::dot(patch.vertices[k] - of.centroid, of.normal));
  return nearest;
}

// Some vertex of `patch` strictly in front of the plane of `of` (beyond rounding at size `scale`).
bool partlyInFront(const Patch& patch, const Patch& of, double scale) {
  for (int k = 0; k < patch.vertexCount; ++k)
    if (glm::dot(patch.vertices[k] - of.centroid, of.normal) > kRounding * scale) return true;
  return false;
}

}  // namespace

double distanceToPatch(const Vec3& point, const Patch& patch) {
  bool inside = true;
  double edges = std::numeric_limits<double>::infinity();
  for (int k = 0; k < patch.vertexCount; ++k) {
    const Vec3& a = patch.vertices[k];
    const Vec3 e = patch.vertices[(k + 1) % patch.vertexCount] - a, w = point - a;
    if (glm::dot(glm::cross(e, w), patch.normal) < 0.0) inside = false;
    const double along = glm::dot(e, e) > 0.0 ? std::clamp(glm::dot(w, e) / glm::dot(e, e), 0.0, 1.0) : 0.0;
    edges = std::min(edges, glm::length(w - along * e));
  }
  return inside ? std::abs(glm::dot(point - patch.centroid, patch.normal)) : edges;
}

bool inNearField(const Patch& shooter, double size, const Patch& receiver) {
  const double r = distanceToPatch(shooter.centroid, receiver);
  if (r < size) return true;
  const double r2 = r * r;
  const double facing = -glm::dot(shooter.normal, receiver.normal);
  const double h = glm::dot(shooter.centroid - receiver.centroid, receiver.normal);
  if (!(facing > 0.0) || !(h > 0.0 && h < size)) return false;
  return facing * shooter.areaM2 / 3.0 * h * h * (r2 - h * h) / (r2 * r2 * r2) > kGapTailLimit;
}

// The gap's term is at most (A / 3) size^2 / r^4 (h < size, facing <= 1).
double nearFieldReach(const Patch& shooter, double size) {
  return std::max(size, std::pow(shooter.areaM2 * size * size / (3.0 * kGapTailLimit), 0.25));
}

std::vector<std::vector<int>> findNearFieldReceivers(const std::vector<Patch>& patches) {
  return findNearFieldReceivers(patches, patches);
}

std::vector<std::vector<int>> findNearFieldReceivers(const std::vector<Patch>& patches,
                                                     const std::vector<Patch>& receivers) {
  NearFieldFinder finder(patches, receivers);
  std::vector<std::vector<int>> near(patches.size());
  for (size_t i = 0; i < patches.size(); ++i) near[i] = finder.receiversNear(static_cast<int>(i));
  return near;
}

NearFieldFinder::NearFieldFinder(const std::vector<Patch>& shooters, const std::vector<Patch>& receivers)
    : shooters_(shooters), receivers_(receivers), near_(shooters.size()), found_(shooters.size(), 0) {
  for (const Patch& p : shooters) size_.push_back(diameter(p));
  for (const Patch& p : receivers) radius_.push_back(spreadOf(p).radius);
  for (double s : size_) largest_ = std::max(largest_, s);
  // Receivers' diameters too, not only their radii: a part's radius is within its whole's diameter,
  // so the receivers split from these stay within the classes.
  for (const Patch& p : receivers) largest_ = std::max(largest_, diameter(p));
}

NearFieldFinder::Cell NearFieldFinder::Grid::cellOf(const Vec3& c) const {
  return Cell{std::llround(std::floor(c.x / cellSize)), std::llround(std::floor(c.y / cellSize)),
              std::llround(std::floor(c.z / cellSize))};
}

NearFieldFinder::Key NearFieldFinder::Grid::keyOf(const Patch& receiver) const {
  const Cell cell = cellOf(receiver.centroid);
  const Vec3 n = receiver.normal * 1e12;  // a unit normal: well within long long
  return Key{cell[0], cell[1], cell[2],
             static_cast<long long>(n.x), static_cast<long long>(n.y), static_cast<long long>(n.z)};
}

NearFieldFinder::Spread NearFieldFinder::spreadOf(const Patch& patch) {
  Spread spread;
  for (int k = 0; k < patch.vertexCount; ++k) {
    const Vec3 d = patch.vertices[k] - patch.centroid;
    spread.bulge = std::max(spread.bulge, std::abs(glm::dot(d, patch.normal)));
    spread.radius = std::max(spread.radius, glm::length(d));
  }
  return spread;
}

// A receiver near the shooter has a vertex in front of the shooter's plane, and the shooter one in
// front of its plane, each by more than the rounding tolerance (at the shooter's size): their sum
// exceeds twice that. Yet were both normals `normal`, the sum would be at most the two bulges;
// their differences from it add at most that difference times the distances involved (centroids
// within reach plus a receiver's radius, vertices within radius of theirs), and 1e-12 of those
// distances covers rounding. Where that bound stays under twice the tolerance, no receiver of the
// stack faces the shooter: parallel, flat copies never do.
bool NearFieldFinder::neverNear(const Patch& shooter, const Spread& spread, double size, double reach,
                                const Stack& stack, const Vec3& normal) {
  const double tilt = glm::length(shooter.normal - normal) + stack.tilt + 1e-12;
  const double distances = reach + spread.radius + 2.0 * stack.spread.radius;
  return spread.bulge + stack.spread.bulge + tilt * distances <= 2.0 * kRounding * size;
}

NearFieldFinder::Grid& NearFieldFinder::gridAt(std::vector<Grid>& grids, size_t k, double cellSize, double smallest) {
  if (grids.size() <= k) grids.resize(k + 1);
  Grid& grid = grids[k];
  if (grid.cellSize == 0.0) {
    grid.cellSize = cellSize;
    grid.smallest = smallest;
    for (size_t j = 0; j < receivers_.size(); ++j)
      if (grid.holds(radius_[j])) grid.sorted.push_back({grid.keyOf(receivers_[j]), static_cast<int>(j)});
    std::sort(grid.sorted.begin(), grid.sorted.end());
    indexStacks(grid);
  }
  return grid;
}

void NearFieldFinder::indexStacks(Grid& grid) const {
  const int n = static_cast<int>(grid.sorted.size());
  grid.centroids.clear();
  grid.radii.clear();
  for (const auto& [key, j] : grid.sorted) {
    grid.centroids.push_back(receivers_[j].centroid);
    grid.radii.push_back(radius_[j]);
  }
  grid.stackAt.assign(n, -1);
  grid.stacks.clear();
  for (int begin = 0, end = 0; begin < n; begin = end) {
    for (end = begin + 1; end < n && grid.sorted[end].first == grid.sorted[begin].first;) ++end;
    if (end - begin < kStackSize) continue;
    Stack stack{end, 0.0, {}};
    const Vec3& normal = receivers_[grid.sorted[begin].second].normal;
    for (int k = begin; k < end; ++k) {
      const Patch& receiver = receivers_[grid.sorted[k].second];
      stack.tilt = std::max(stack.tilt, glm::length(receiver.normal - normal));
      const Spread spread = spreadOf(receiver);
      stack.spread.bulge = std::max(stack.spread.bulge, spread.bulge);
      stack.spread.radius = std::max(stack.spread.radius, spread.radius);
    }
    grid.stackAt[begin] = static_cast<int>(grid.stacks.size());
    grid.stacks.push_back(stack);
  }
}

void NearFieldFinder::receiversSplit(const std::vector<int>& origin, const std::vector<char>& split) {
  const std::vector<int> newIndex = newIndices(origin, split);
  std::vector<int> children;
  for (size_t e = 0; e < origin.size(); ++e)
    if (split[origin[e]]) children.push_back(static_cast<int>(e));
  std::vector<double> radius(receivers_.size());
  for (size_t j = 0; j < origin.size(); ++j)
    radius[j] = split[origin[j]] ? spreadOf(receivers_[j]).radius : radius_[origin[j]];
  radius_ = std::move(radius);
  for (std::vector<Grid>* grids : {&small_, &large_})
    for (Grid& grid : *grids) {
      if (grid.cellSize == 0.0) continue;
      // Renumbering keeps the order of the receivers that did not split (it is monotone): so the
      // merge gives the fresh sort's order exactly.
      std::vector<std::pair<Key, int>> kept, made;
      kept.reserve(grid.sorted.size());
      for (const auto& [key, j] : grid.sorted)
        if (newIndex[j] >= 0) kept.push_back({key, newIndex[j]});
      for (int e : children)
        if (grid.holds(radius_[e])) made.push_back({grid.keyOf(receivers_[e]), e});
      std::sort(made.begin(), made.end());
      grid.sorted.resize(kept.size() + made.size());
      std::merge(kept.begin(), kept.end(), made.begin(), made.end(), grid.sorted.begin());
      indexStacks(grid);
    }
  for (std::vector<int>& near : near_) near.clear();
  std::fill(found_.begin(), found_.end(), 0);
}

void NearFieldFinder::search(const Grid& grid, int i, const Spread& spread, double reach) {
  if (grid.sorted.empty()) return;
  std::vector<int>& near = near_[i];
  const double size = size_[i];
  const bool selfReceives = &shooters_ == &receivers_;
  const Patch& shooter = shooters_[i];
  // A receiver's nearest point within reach puts its centroid within reach plus its radius.
  const double box = reach + grid.cellSize;
  const Cell low = grid.cellOf(shooter.centroid - Vec3(box)), high = grid.cellOf(shooter.centroid + Vec3(box));
  constexpr long long kLeast = std::numeric_limits<long long>::min();
  for (long long x = low[0]; x <= high[0]; ++x)
    for (long long y = low[1]; y <= high[1]; ++y) {
      const Key first{x, y, low[2], kLeast, kLeast, kLeast};
      auto it = std::lower_bound(grid.sorted.begin(), grid.sorted.end(), std::pair<Key, int>{first, -1});
      for (; it != grid.sorted.end() && it->first[0] == x && it->first[1] == y && it->first[2] <= high[2]; ++it) {
        const size_t k = it - grid.sorted.begin();
        const int j = it->second;
        if (const int s = grid.stackAt[k];
            s >= 0 && neverNear(shooter, spread, size, reach, grid.stacks[s], receivers_[j].normal)) {
          it = grid.sorted.begin() + grid.stacks[s].end - 1;  // on to the stack's last
          continue;
        }
        ++examined_;
        // The slack covers rounding in the nearest point, which the bound must not cut off.
        const double farthest = (reach + grid.radii[k]) * (1.0 + 1e-9);
        if ((selfReceives && j == i) || !(glm::length(grid.centroids[k] - shooter.centroid) < farthest)) continue;
        if (inNearField(shooter, size, receivers_[j]) && partlyInFront(receivers_[j], shooter, size) &&
            partlyInFront(shooter, receivers_[j], size))
          near.push_back(j);
      }
    }
}

// Shooters in classes by diameter, halving from the largest; a class's small receivers are in cells
// half as wide as its largest diameter, so a shooter searches only the cells its reach
// (nearFieldReach, at most 3.1 diameters) overlaps, and never cells much wider than itself; each
// larger receiver is in cells about its own size, searched within the reach plus that size.
const std::vector<int>& NearFieldFinder::receiversNear(int i) {
  std::vector<int>& near = near_[i];
  const double size = size_[i];
  if (found_[i] || !(size > 0.0)) return near;  // a shooter of no extent has no near receivers
  found_[i] = 1;
  const Spread spread = spreadOf(shooters_[i]);
  const double reach = nearFieldReach(shooters_[i], size);
  size_t k = 0;
  double top = largest_;
  while (size <= 0.5 * top) top *= 0.5, ++k;
  search(gridAt(small_, k, 0.5 * top, -1.0), i, spread, reach);
  for (size_t b = 0; b <= k; ++b) {
    const double cell = largest_ / std::pow(2.0, static_cast<double>(b));
    search(gridAt(large_, b, cell, 0.5 * cell), i, spread, reach);
  }
  std::sort(near.begin(), near.end());
  return near;
}

namespace {

// The mean over the shooter's area of the point-to-polygon form factor to the receiver's front.
double meanFormFactor(const Patch& shooter, const Patch& receiver, int subdivisions) {
  const LocalPolygon local = toShooterFrame(shooter, receiver);
  std::array<Vec3, 4> shifted{};
  const std::span<const Vec3> polygon{shifted.data(), static_cast<size_t>(local.vertexCount)};
  const double m = subdivisions;
  double weighted = 0.0, area = 0.0;
  // The fan of triangles from vertex 0, each cut into m^2 equal triangles: m(m+1)/2 upright ones
  // at barycentric steps (3i+1, 3j+1)/3m, m(m-1)/2 inverted ones at (3i+2, 3j+2)/3m.
  const Vec3 a = toShooterFrame(shooter, shooter.vertices[0]);
  for (int t = 1; t + 1 < shooter.vertexCount; ++t) {
    const Vec3 ab = toShooterFrame(shooter, shooter.vertices[t]) - a;
    const Vec3 ac = toShooterFrame(shooter, shooter.vertices[t + 1]) - a;
    const double triangleArea = 0.5 * glm::length(glm::cross(ab, ac));
    double sum = 0.0;
    auto at = [&](double s, double u) {
      Vec3 p = a + s * ab + u * ac;
      p.z = 0.0;  // on the shooter's plane, its normal +z
      // Behind the receiver's plane the closed form, blind to which side it sees, gives the back's.
      if (!(glm::dot(local.normal, p) > local.planeOffset)) return;
      for (int k = 0; k < local.vertexCount; ++k) shifted[k] = local.vertices[k] - p;
      sum += pointToPolygonFormFactor(polygon);
    };
    for (int i = 0; i < subdivisions; ++i)
      for (int j = 0; i + j < subdivisions; ++j) {
        at((3 * i + 1) / (3 * m), (3 * j + 1) / (3 * m));
        if (i + j + 1 < subdivisions) at((3 * i + 2) / (3 * m), (3 * j + 2) / (3 * m));
      }
    weighted += sum * triangleArea / (m * m);
    area += triangleArea;
  }
  return area > 0.0 ? weighted / area : 0.0;
}

}  // namespace

double areaToAreaFormFactor(const Patch& shooter, const Patch& receiver, int subdivisions) {
  // Reciprocity (A_s F_sr = A_r F_rs): a receiver no larger than the shooter (an element, or a cell
  // of the same grid) is sampled instead, at sub-triangles no larger, so at no more points. Where the
  // receiver lies wholly in front of the shooter, every point of it sees the shooter's front, and the
  // closed form from it clips away exactly the part of the shooter behind the receiver's plane.
  // Sizes compare with a slack: equal cells, or an element a quarter of its patch (half its size),
  // are so only to rounding, or to where the grid cuts a model moved by a nanometre, and the choice
  // must not turn on that: the two samplings differ by their quadrature errors (0.6 % for a floor
  // cell beside a block).
  constexpr double kSizeSlack = 1e-6;
  const double shooterSize = diameter(shooter), ratio = diameter(receiver) / shooterSize;
  // Apart across a gap narrower than the sample points are spaced, each point sees the other plate
  // as a spike under it, or misses it: the exact contour integral instead (1 m plates 1 cm apart
  // read 1.5 % high sampled).
  if (const double gap = std::min(distanceInFront(receiver, shooter), distanceInFront(shooter, receiver));
      gap > kRounding * shooterSize && gap < shooterSize / subdivisions)
    return polygonToPolygonFormFactor({shooter.vertices.data(), static_cast<size_t>(shooter.vertexCount)},
                                      {receiver.vertices.data(), static_cast<size_t>(receiver.vertexCount)});
  if (ratio < 1.0 + kSizeSlack && whollyInFront(receiver, shooter, shooterSize) && receiver.areaM2 > 0.0 &&
      shooter.areaM2 > 0.0) {
    const int m = std::max(2, static_cast<int>(std::ceil(subdivisions * (ratio - kSizeSlack))));
    return meanFormFactor(receiver, shooter, m) * (receiver.areaM2 / shooter.areaM2);
  }
  return meanFormFactor(shooter, receiver, subdivisions);
}

namespace {

// Calls visit(r, k) for each row entry r whose receiver is near receiver k (both lists ascending).
template <typename Visit>
void forNearEntries(const FormFactorRow& row, const std::vector<int>& nearReceivers, Visit visit) {
  auto next = nearReceivers.begin();
  for (size_t r = 0; r < row.receivers.size() && next != nearReceivers.end(); ++r) {
    next = std::lower_bound(next, nearReceivers.end(), row.receivers[r]);
    if (next != nearReceivers.end() && *next == row.receivers[r]) visit(r, static_cast<size_t>(next - nearReceivers.begin()));
  }
}

}  // namespace

void completeNearFieldPairs(const Patch& shooter, const std::vector<Patch>& receivers,
                            const std::vector<int>& nearReceivers, const FormFactorRow& row,
                            std::vector<NearFieldPair>& pairs) {
  pairs.resize(nearReceivers.size());
  forNearEntries(row, nearReceivers, [&](size_t, size_t k) {
    if (pairs[k].computed) return;
    const Patch& receiver = receivers[nearReceivers[k]];
    pairs[k] = {pointToPolygonFormFactor(toShooterFrame(shooter, receiver).corners()),
                areaToAreaFormFactor(shooter, receiver), true};
  });
}

void correctNearField(FormFactorRow& row, const std::vector<int>& nearReceivers, std::span<const NearFieldPair> pairs) {
  if (nearReceivers.empty()) return;
  const double before = row.hitFraction(), escaped = row.escapedFraction();
  std::vector<char> near(row.receivers.size(), 0);
  double shortfall = 0.0;  // what the near receivers lose to their area-to-area values (negative: gain)
  forNearEntries(row, nearReceivers, [&](size_t r, size_t k) {
    const NearFieldPair& pair = pairs[k];
    if (!(pair.point > 0.0) || !(pair.area > 0.0)) return;  // edge-on to the centroid: nothing to scale
    const double corrected = std::min(1.0, row.formFactors[r] / pair.point) * pair.area;
    shortfall += row.formFactors[r] - corrected;
    row.formFactors[r] = corrected;
    near[r] = 1;
  });
  // Seen from the rest of the shooter, the near receivers subtend that much less than from its
  // centroid, and what lies beyond them that much more: the far receivers, the backs and the
  // background, each in proportion to what the projection saw of it. An open gap seen edge-on
  // (plates 1 cm apart) passes its share out of the scene; a crack between patches of a closed room
  // (a T-junction, a pixel here and there) is a thousandth of what lies beyond, and so is its share.
  double far = row.backFaces;
  for (size_t r = 0; r < near.size(); ++r)
    if (!near[r]) far += row.formFactors[r];
  const double beyond = far + escaped;
  if (beyond > 0.0 && shortfall > -beyond) {
    const double scale = 1.0 + shortfall / beyond;
    for (size_t r = 0; r < near.size(); ++r)
      if (!near[r]) row.formFactors[r] *= scale;
    row.backFaces *= scale;
    return;
  }
  // Nothing beyond to take the difference, or too little to give a gain: the row keeps its total.
  const double after = row.hitFraction();
  if (!(after > 0.0) || after == before) return;
  for (double& f : row.formFactors) f *= before / after;
  row.backFaces *= before / after;
}

}  // namespace radmesh
