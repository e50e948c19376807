#include "solver/projection/scan_conversion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>

#include "solver/geometry/polygon_2d.h"

namespace radmesh {

namespace {

// The one formula every pixel decision goes through, so spans and single pixels agree bit for bit.
inline bool inside(const EdgeFunction& e, double cx, double cy) {
  const double value = (cx - e.startX) * e.dirY - (cy - e.startY) * e.dirX;
  return value > 0.0 || (value == 0.0 && e.ownsTies);
}

// Pixel range [begin, end) whose centres (i + 0.5) may lie in [low, high], widened by one pixel
// (the edge functions decide) and clamped to [0, size].
std::pair<int, int> pixelRange(double low, double high, int size) {
  const double begin = std::clamp(std::ceil(low - 0.5) - 1.0, 0.0, static_cast<double>(size));
  const double end = std::clamp(std::floor(high - 0.5) + 2.0, 0.0, static_cast<double>(size));
  return {static_cast<int>(begin), static_cast<int>(end)};
}

// First column in [lo, hi) where `pass` holds, for a predicate monotone in the column; hi if none.
// `guess` (where the edge crosses the row) makes this a step or two.
template <typename Pass>
int firstPassing(double guess, int lo, int hi, Pass pass) {
  int g = !(guess > lo) ? lo : !(guess < hi) ? hi : static_cast<int>(guess);
  while (g > lo && pass(g - 1)) --g;
  while (g < hi && !pass(g)) ++g;
  return g;
}

}  // namespace

bool setupPolygon(const ScreenPolygon& polygon, int width, int height, int id, int rank,
                  PolygonSetup& setup) {
  const int n = polygon.vertexCount;
  if (n < 3) return false;
  const auto& v = polygon.vertices;
  double doubleArea = 0.0;
  for (int k = 1; k + 1 < n; ++k) doubleArea += cross2(v[k] - v[0], v[k + 1] - v[0]);
  if (!(std::abs(doubleArea) > 0.0) || !std::isfinite(doubleArea)) return false;
  const double orientation = doubleArea > 0.0 ? 1.0 : -1.0;

  glm::dvec2 low = v[0], high = v[0];
  for (int k = 1; k < n; ++k) {
    low = glm::min(low, v[k]);
    high = glm::max(high, v[k]);
  }
  std::tie(setup.columnBegin, setup.columnEnd) = pixelRange(low.x, high.x, width);
  std::tie(setup.rowBegin, setup.rowEnd) = pixelRange(low.y, high.y, height);
  if (setup.columnBegin >= setup.columnEnd || setup.rowBegin >= setup.rowEnd) return false;

  setup.id = id;
  setup.rank = rank;
  setup.areaPixels = 0.5 * std::abs(doubleArea);
  setup.depthTieTolerance = polygon.parallel ? kBeamDepthTieTolerance : kDepthTieTolerance;
  setup.inverseDepthX = polygon.inverseDepthX;
  setup.inverseDepthY = polygon.inverseDepthY;
  setup.inverseDepthC = polygon.inverseDepthC;
  setup.edgeCount = 0;
  double longestSquared = 0.0;
  for (int k = 0; k < n; ++k) {
    const glm::dvec2 p = v[k];
    const glm::dvec2 q = v[(k + 1) % n];
    if (p == q) continue;  // a repeated vertex bounds nothing
    const bool forward = std::tie(p.x, p.y) < std::tie(q.x, q.y);
    const glm::dvec2 start = forward ? p : q;
    // Counter-clockwise polygons keep their inside on the left of each edge as traversed; the
    // sign flip is exact, so a neighbour across the edge evaluates exactly the negated value.
    const double sign = -(forward ? 1.0 : -1.0) * orientation;
    const glm::dvec2 dir = sign * (forward ? q - p : p - q);
    longestSquared = std::max(longestSquared, glm::dot(dir, dir));
    EdgeFunction& e = setup.edges[setup.edgeCount++];
    e.startX = start.x;
    e.startY = start.y;
    e.dirX = dir.x;
    e.dirY = dir.y;
    // The edge as traversed with the inside on its left; neighbours across it traverse it the
    // other way, so exactly one of them owns centres lying on it.
    const glm::dvec2 traversed = -dir;
    e.ownsTies = traversed.y > 0.0 || (traversed.y == 0.0 && traversed.x < 0.0);
    e.inverseSlope = dir.y != 0.0 ? dir.x / dir.y : 0.0;  // unused for edges along a row
    // Rounding of the edge's value and of its crossing column stays below a few ulps of the
    // magnitudes involved; a generous multiple of that is safe.
    const double magnitude = std::abs(start.x) + width + 1.0 + (std::abs(start.y) + height + 1.0) * std::abs(e.inverseSlope);
    e.crossingSlack = 64.0 * std::numeric_limits<double>::epsilon() * magnitude;
  }
  setup.widthPixels = setup.areaPixels / std::sqrt(longestSquared);
  return setup.edgeCount >= 3;
}

bool setUpProjection(const LocalPolygon& patch, const ProjectionFace& face, double nearDepth, int id, int rank,
                     PolygonSetup& setup) {
  ScreenPolygon screen;
  return projectOntoFace(patch, face, nearDepth, screen) && setupPolygon(screen, face.width, face.height, id, rank, setup);
}

bool covers(const PolygonSetup& setup, int column, int row) {
  if (column < setup.columnBegin || column >= setup.columnEnd || row < setup.rowBegin ||
      row >= setup.rowEnd)
    return false;
  const double cx = column + 0.5;
  const double cy = row + 0.5;
  for (int k = 0; k < setup.edgeCount; ++k)
    if (!inside(setup.edges[k], cx, cy)) return false;
  return true;
}

namespace {

// 1/depth = X (column + 0.5) + [Y (row + 0.5) + C], the bracket once per row: spans and single
// pixels group the sum the same way, so they agree bit for bit.
double rowInverseDepth(const PolygonSetup& setup, int row) {
  return setup.inverseDepthY * (row + 0.5) + setup.inverseDepthC;
}

}  // namespace

double inverseDepthAt(const PolygonSetup& setup, int column, int row) {
  return setup.inverseDepthX * (column + 0.5) + rowInverseDepth(setup, row);
}

std::vector<int> depthTieRanks(const std::vector<Patch>& patches) {
  std::vector<int> order(patches.size());
  std::iota(order.begin(), order.end(), 0);
  auto key = [&](int i) {
    const Patch& p = patches[i];
    return std::tie(p.centroid.x, p.centroid.y, p.centroid.z, p.areaM2, p.material);
  };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key(a) < key(b); });
  std::vector<int> rank(patches.size());
  for (size_t r = 0; r < order.size(); ++r) rank[order[r]] = static_cast<int>(r);
  return rank;
}

std::pair<int, int> rowSpan(const PolygonSetup& setup, int row) {
  const double cy = row + 0.5;
  int left = setup.columnBegin;
  int right = setup.columnEnd;
  for (int k = 0; k < setup.edgeCount && left < right; ++k) {
    const EdgeFunction& e = setup.edges[k];
    auto pass = [&](int column) { return inside(e, column + 0.5, cy); };
    if (e.dirY == 0.0) {  // parallel to the rows: all of the row or none
      if (!pass(left)) right = left;
      continue;
    }
    // The first column whose centre lies past the edge (on the inside for a left edge, the
    // outside for a right one): ceil(t). When the crossing is clear of every pixel centre by
    // more than rounding can move it, that is exact; otherwise the edge function decides,
    // column by column. (Integer ceil: std::ceil is a library call on baseline x86-64.)
    const double t = e.startX + (cy - e.startY) * e.inverseSlope - 0.5;
    const double slack = e.crossingSlack;
    int first;
    if (t >= left - 2.0 && t <= right + 2.0) {
      int g = static_cast<int>(t);  // truncation: ceil for negative t ...
      g += g < t;                   // ... and for positive t after this (no branch to mispredict)
      if (g - t > slack && t - (g - 1) > slack)
        first = std::clamp(g, left, right);
      else
        first = e.dirY > 0.0 ? firstPassing(g, left, right, pass)
                             : firstPassing(g, left, right, [&](int column) { return !pass(column); });
    } else if (slack < 1.0 && t < left) {
      first = left;  // crossing well left of the span
    } else if (slack < 1.0 && t > right) {
      first = right;  // well right of it
    } else {  // not a number, or magnitudes rounding can move by pixels
      first = e.dirY > 0.0 ? firstPassing(left, left, right, pass)
                           : firstPassing(left, left, right, [&](int column) { return !pass(column); });
    }
    if (e.dirY > 0.0)
      left = first;
    else
      right = first;
  }
  return {left, std::max(left, right)};
}

long long coveredPixelCount(const PolygonSetup& setup) {
  long long covered = 0;
  for (int row = setup.rowBegin; row < setup.rowEnd; ++row) {
    const auto [left, right] = rowSpan(setup, row);
    covered += right - left;
  }
  return covered;
}

long long rasterise(const PolygonSetup& setup, ItemBuffer& buffer, int rowBegin, int rowEnd,
                    std::span<const int> rankOf) {
  const int firstRow = std::max(rowBegin, setup.rowBegin);
  const int lastRow = std::min(rowEnd, setup.rowEnd);
  long long covered = 0;
  for (int row = firstRow; row < lastRow; ++row) {
    const auto [left, right] = rowSpan(setup, row);
    covered += right - left;
    int* items = buffer.items.data() + static_cast<std::ptrdiff_t>(row) * buffer.width;
    double* depths = buffer.inverseDepth.data() + static_cast<std::ptrdiff_t>(row) * buffer.width;
    const double rowPart = rowInverseDepth(setup, row);
    for (int column = left; column < right; ++column) {
      const double inverseDepth = setup.inverseDepthX * (column + 0.5) + rowPart;
      const int there = items[column];
      if (there == ItemBuffer::kNone || closer(inverseDepth, setup.rank, depths[column], rankOf[there], setup.depthTieTolerance)) {
        items[column] = setup.id;
        depths[column] = inverseDepth;
      }
    }
  }
  return covered;
}

}  // namespace radmesh
