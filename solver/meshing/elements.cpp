#include "solver/meshing/elements.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "solver/scene/scene_error.h"
#include "solver/scene/solve_options.h"

namespace radmesh {

namespace {

// An element of `parent` with the given corners (counter-clockwise around its normal): its area
// and area centroid from the fan of triangles, the rest its parent's.
Patch elementOf(const Patch& parent, std::initializer_list<Vec3> corners) {
  Patch e = parent;
  e.vertexCount = static_cast<int>(corners.size());
  std::copy(corners.begin(), corners.end(), e.vertices.begin());
  double area = 0.0;
  Vec3 centroid{0.0};
  for (int k = 1; k + 1 < e.vertexCount; ++k) {
    const double a = 0.5 * glm::dot(glm::cross(e.vertices[k] - e.vertices[0], e.vertices[k + 1] - e.vertices[0]),
                                    parent.normal);
    area += a;
    centroid += a * (e.vertices[0] + e.vertices[k] + e.vertices[k + 1]) / 3.0;
  }
  e.areaM2 = area;
  e.centroid = centroid / area;
  return e;
}

void cutQuad(const Patch& p, int n, std::vector<Patch>& out) {
  const auto at = [&](int i, int j) {  // the bilinear point (i/n along v0 -> v1, j/n along v0 -> v3)
    const double s = static_cast<double>(i) / n, t = static_cast<double>(j) / n;
    return (1.0 - t) * ((1.0 - s) * p.vertices[0] + s * p.vertices[1]) +
           t * ((1.0 - s) * p.vertices[3] + s * p.vertices[2]);
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) out.push_back(elementOf(p, {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}));
}

void cutTriangle(const Patch& p, int n, std::vector<Patch>& out) {
  const auto at = [&](int i, int j) {  // v0 + i/n (v1 - v0) + j/n (v2 - v0)
    return p.vertices[0] + (static_cast<double>(i) / n) * (p.vertices[1] - p.vertices[0]) +
           (static_cast<double>(j) / n) * (p.vertices[2] - p.vertices[0]);
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i + j < n; ++i) {
      out.push_back(elementOf(p, {at(i, j), at(i + 1, j), at(i, j + 1)}));
      if (i + j + 1 < n) out.push_back(elementOf(p, {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}));
    }
}

// The four children of an element (Elements in elements.h gives their corners).
void splitInFour(const Patch& e, std::vector<Patch>& out) {
  const auto mid = [&](int a, int b) { return 0.5 * (e.vertices[a] + e.vertices[b]); };
  if (e.vertexCount == 4) {
    const Vec3 m01 = mid(0, 1), m12 = mid(1, 2), m23 = mid(2, 3), m30 = mid(3, 0), c = 0.5 * (m01 + m23);
    for (auto corners : {std::initializer_list<Vec3>{e.vertices[0], m01, c, m30}, {m01, e.vertices[1], m12, c},
                         {c, m12, e.vertices[2], m23}, {m30, c, m23, e.vertices[3]}})
      out.push_back(elementOf(e, corners));
  } else {
    const Vec3 m01 = mid(0, 1), m12 = mid(1, 2), m20 = mid(2, 0);
    for (auto corners : {std::initializer_list<Vec3>{e.vertices[0], m01, m20}, {m01, e.vertices[1], m12},
                         {m20, m12, e.vertices[2]}, {m12, m20, m01}})
      out.push_back(elementOf(e, corners));
  }
}

}  // namespace

double longestEdge(const Patch& patch) {
  double longest = 0.0;
  for (int k = 0; k < patch.vertexCount; ++k)
    longest = std::max(longest, glm::length(patch.vertices[(k + 1) % patch.vertexCount] - patch.vertices[k]));
  return longest;
}

int elementCuts(const Patch& patch, double minElementM) {
  if (minElementM == 0.0) return 2;
  const double longest = longestEdge(patch);
  // A patch exactly a whole number of elements long is cut that many times, not once more for rounding.
  // At most 2^20 cuts (more elements than any limit), so that a tiny minElementM is refused, not overflowed.
  return static_cast<int>(std::clamp(std::ceil(longest / minElementM * (1.0 - 1e-12)), 1.0, 1048576.0));
}

double countElements(const std::vector<Patch>& patches, double minElementM) {
  double count = 0.0;
  for (const Patch& p : patches) count += std::pow(elementCuts(p, minElementM), 2.0);
  return count;
}

double checkElementCount(const std::vector<Patch>& patches, double minElementM, const ElementLimit& limit,
                         const std::string& what) {
  checkMinElement(minElementM);
  const double count = countElements(patches, minElementM);
  if (count > static_cast<double>(limit.count)) {
    const std::string fix = minElementM > 0.0
        ? fmt::format("use a larger --min-element (about {:.3g} m or more)",
                      minElementM * std::sqrt(count / static_cast<double>(limit.count)) * 1.1)
        : "give a larger --cell or --subdivide off";
    throw OptionError(fmt::format("--min-element {} m {} the {} patches into {:.3g} elements, more than the "
                                  "limit of {}{}; {}", minElementM, what, patches.size(), count, limit.count,
                                  limit.why, fix));
  }
  return count;
}

ElementLimit elementLimit(std::size_t memoryBytes) {
  const std::size_t byMemory = memoryBytes / 2 / kPeakBytesPerElement;
  if (memoryBytes == 0 || byMemory >= kMaxElements) return {};
  return {byMemory, fmt::format(" (half of the {:.1f} GiB of memory this process may use, at about {} bytes an "
                                "element at a solve's peak)", static_cast<double>(memoryBytes) / (1u << 30),
                                kPeakBytesPerElement)};
}

void checkElementBudget(const std::vector<Patch>& patches, bool adaptive, double minElementM) {
  checkElementCount(patches, minElementM, elementLimit(), adaptive ? "could let adaptive subdivision split" : "would cut");
}

Elements subdivideUniform(const std::vector<Patch>& patches, double minElementM, const ElementLimit& limit) {
  const double count = checkElementCount(patches, minElementM, limit, "would cut");
  Elements out;
  out.elements.reserve(static_cast<std::size_t>(count));
  out.first.reserve(patches.size() + 1);
  for (std::size_t p = 0; p < patches.size(); ++p) {
    out.first.push_back(static_cast<int>(out.elements.size()));
    const int n = elementCuts(patches[p], minElementM);
    if (patches[p].vertexCount == 4)
      cutQuad(patches[p], n, out.elements);
    else
      cutTriangle(patches[p], n, out.elements);
    out.patchOf.resize(out.elements.size(), static_cast<int>(p));
  }
  out.first.push_back(static_cast<int>(out.elements.size()));
  out.level.assign(out.elements.size(), 0);
  return out;
}

Elements patchesAsElements(const std::vector<Patch>& patches) {
  Elements out;
  out.elements = patches;
  for (size_t p = 0; p <= patches.size(); ++p) out.first.push_back(static_cast<int>(p));
  out.patchOf.assign(out.first.begin(), out.first.end() - 1);
  out.level.assign(patches.size(), 0);
  return out;
}

std::vector<int> splitElements(Elements& elements, const std::vector<char>& split) {
  // In place, from the back: each split adds three elements, and the vectors keep their memory
  // from one round of splits to the next (a fresh copy of them a round was 8 % of a corridor's
  // adaptive solve, much of it faulting new pages in).
  const size_t n = elements.elements.size();
  const size_t count = n + 3 * static_cast<size_t>(std::count(split.begin(), split.end(), 1));
  std::vector<int> origin(count);
  elements.elements.resize(count);
  elements.patchOf.resize(count);
  elements.level.resize(count);
  std::vector<Patch> children;
  size_t at = count;
  int end = elements.first.back();  // the old end of patch p, whose first is overwritten below
  elements.first.back() = static_cast<int>(count);
  for (size_t p = elements.first.size() - 1; p-- > 0;) {
    const int begin = elements.first[p];
    for (int e = end - 1; e >= begin; --e) {
      const int level = elements.level[e];
      if (split[e]) {
        children.clear();
        splitInFour(elements.elements[e], children);
        for (size_t c = children.size(); c-- > 0;) {
          elements.elements[--at] = children[c];
          origin[at] = e, elements.patchOf[at] = static_cast<int>(p), elements.level[at] = level + 1;
        }
      } else {
        elements.elements[--at] = elements.elements[e];
        origin[at] = e, elements.patchOf[at] = static_cast<int>(p), elements.level[at] = level;
      }
    }
    elements.first[p] = static_cast<int>(at);
    end = begin;
  }
  return origin;
}

std::vector<int> newIndices(const std::vector<int>& origin, const std::vector<char>& split) {
  std::vector<int> index(split.size(), -1);
  for (size_t e = 0; e < origin.size(); ++e)
    if (!split[origin[e]]) index[origin[e]] = static_cast<int>(e);
  return index;
}

Elements splitToLevels(const std::vector<Patch>& patches, const std::vector<int>& levels) {
  constexpr int kMaxLevel = 31;  // a leaf's share of its patch, 4^-level, counted in a u64
  int deepest = 0;
  for (int level : levels) {
    if (level < 0 || level > kMaxLevel) throw std::invalid_argument(fmt::format("an element of level {}", level));
    deepest = std::max(deepest, level);
  }
  auto share = [&](int level) { return std::uint64_t{1} << (2 * (deepest - level)); };
  Elements elements = patchesAsElements(patches);
  // Each pass splits the elements whose leaves lie deeper: every element takes the leaves that
  // cover it, in order, and splits unless that is one leaf of its own level.
  for (bool splitting = true; splitting;) {
    std::vector<char> split(elements.elements.size(), 0);
    size_t at = 0;
    for (size_t e = 0; e < elements.elements.size(); ++e) {
      const std::uint64_t needed = share(elements.level[e]);
      std::uint64_t covered = 0;
      const size_t from = at;
      while (covered < needed && at < levels.size()) covered += share(levels[at++]);
      if (covered != needed) throw std::invalid_argument("element levels that do not tile their patches");
      split[e] = at - from > 1;
    }
    if (at != levels.size()) throw std::invalid_argument("more element levels than the patches hold");
    splitting = std::find(split.begin(), split.end(), 1) != split.end();
    if (splitting) splitElements(elements, split);
  }
  return elements;
}

}  // namespace radmesh
