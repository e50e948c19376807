#include "solver/geometry/polygon_convex.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <unordered_map>

#include "solver/geometry/edge_key.h"
#include "solver/geometry/polygon_triangulate.h"

namespace radmesh {

bool isConvex(const std::vector<Vec2>& ccw, double noiseM) {
  std::vector<Vec2> p;  // without repeated vertices, which have no direction
  for (const Vec2& v : ccw)
    if (p.empty() || glm::length(v - p.back()) > noiseM) p.push_back(v);
  while (p.size() > 1 && glm::length(p.front() - p.back()) <= noiseM) p.pop_back();
  if (p.size() < 3) return false;
  double turning = 0.0;
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec2& a = p[(i + p.size() - 1) % p.size()];
    const Vec2& b = p[i];
    const Vec2& c = p[(i + 1) % p.size()];
    if (sideOfLine(a, c, b) > noiseM) return false;  // reflex
    turning += std::atan2(cross2(b - a, c - b), glm::dot(b - a, c - b));
  }
  // Once around: a star polygon turns left everywhere yet winds twice; a spike turns by pi.
  return std::abs(turning - 2.0 * std::numbers::pi) < 1e-6;
}

namespace {

// Hertel–Mehlhorn: drop each diagonal whose removal leaves both of its ends convex. Pieces are
// index cycles; `owner` maps each directed edge to the piece that has it.
class DiagonalMerger {
 public:
  DiagonalMerger(const std::vector<Vec2>& p, double noiseM) : p_(p), noise_(noiseM) {}

  std::vector<std::vector<int>> run(const std::vector<std::array<int, 3>>& triangles) {
    for (const auto& t : triangles) {
      pieces_.push_back({t[0], t[1], t[2]});
      for (int k = 0; k < 3; ++k)
        owner_[directedEdgeKey(t[k], t[(k + 1) % 3])] = static_cast<int>(pieces_.size()) - 1;
    }
    std::vector<std::pair<int, int>> diagonals;
    for (const auto& [key, piece] : owner_) {
      const int from = static_cast<int>(key >> 32), to = static_cast<int>(key & 0xffffffffu);
      if (from < to && owner_.count(directedEdgeKey(to, from))) diagonals.emplace_back(from, to);
    }
    // Long diagonals first: removing them tends to leave fat pieces. Ties by index: deterministic.
    std::sort(diagonals.begin(), diagonals.end(), [&](const auto& x, const auto& y) {
      const double lx = glm::length(p_[x.second] - p_[x.first]);
      const double ly = glm::length(p_[y.second] - p_[y.first]);
      return lx != ly ? lx > ly : x < y;
    });
    for (const auto& [i, j] : diagonals) tryMerge(i, j);
    std::vector<std::vector<int>> result;
    for (auto& piece : pieces_)
      if (!piece.empty()) result.push_back(std::move(piece));
    return result;
  }

 private:
  // Piece a holds edge i->j, piece b holds j->i; their union, without the diagonal, runs
  // j .. i through a and then i .. j through b.
  void tryMerge(int i, int j) {
    const int a = owner_.at(directedEdgeKey(i, j)), b = owner_.at(directedEdgeKey(j, i));
    std::vector<int> merged = rotatedToStart(pieces_[a], j);       // j, ..., i
    const std::vector<int> fromB = rotatedToStart(pieces_[b], i);  // i, b1, ..., bk, j
    const size_t sizeA = merged.size();
    merged.insert(merged.end(), fromB.begin() + 1, fromB.end() - 1);
    const auto notReflex = [&](size_t at) {
      const size_t n = merged.size();
      return sideOfLine(p_[merged[(at + n - 1) % n]], p_[merged[(at + 1) % n]], p_[merged[at]]) <= noise_;
    };
    if (!notReflex(sizeA - 1) || !notReflex(0)) return;
    owner_.erase(directedEdgeKey(i, j));
    owner_.erase(directedEdgeKey(j, i));
    for (size_t k = 0; k < merged.size(); ++k) {
      const std::uint64_t key = directedEdgeKey(merged[k], merged[(k + 1) % merged.size()]);
      if (owner_.count(key)) owner_[key] = a;
    }
    pieces_[a] = std::move(merged);
    pieces_[b].clear();
  }

  static std::vector<int> rotatedToStart(const std::vector<int>& cycle, int first) {
    std::vector<int> out(cycle);
    std::rotate(out.begin(), std::find(out.begin(), out.end(), first), out.end());
    return out;
  }

  const std::vector<Vec2>& p_;
  double noise_;
  std::vector<std::vector<int>> pieces_;
  std::unordered_map<std::uint64_t, int> owner_;
};

}  // namespace

std::vector<std::vector<Vec2>> convexPieces(const std::vector<Vec2>& ccw, double noiseM) {
  const auto cycles = DiagonalMerger(ccw, noiseM).run(triangulatePolygon(ccw, noiseM));
  std::vector<std::vector<Vec2>> pieces;
  for (const auto& cycle : cycles) {
    std::vector<Vec2>& piece = pieces.emplace_back();
    for (int index : cycle) piece.push_back(ccw[index]);
  }
  return pieces;
}

namespace {

bool hasRepeatedVertex(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(), [](const Vec2& a, const Vec2& b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  return std::adjacent_find(points.begin(), points.end()) != points.end();
}

}  // namespace

std::vector<std::vector<Vec2>> convexCover(const std::vector<Vec2>& ccw, double noiseM, std::string& crossing) {
  crossing.clear();
  std::vector<std::vector<Vec2>> pieces = isConvex(ccw, noiseM) ? std::vector<std::vector<Vec2>>{ccw}
                                                                 : convexPieces(ccw, noiseM);
  const double area = signedArea(ccw);
  double total = 0.0;
  for (const auto& piece : pieces) total += signedArea(piece);
  if (!(std::abs(total - area) <= 1e-6 * area)) {
    crossing = fmt::format("its convex parts cover {:.6g} of its {:.6g} projected square metres", total, area);
    return pieces;
  }
  // An outline that goes round twice over the same vertices has parts covered twice, which the
  // areas above count twice on both sides. Only a repeated vertex lets it (a hole's seam does too,
  // but leaves every part covered once): there, each part must lie inside exactly once.
  if (hasRepeatedVertex(ccw))
    for (const auto& piece : pieces) {
      Vec2 inside{0.0};
      for (const Vec2& q : piece) inside += q;
      if (const int times = windingNumber(ccw, inside / static_cast<double>(piece.size())); times != 1) {
        crossing = fmt::format("its outline goes round part of it {} times", times);
        return pieces;
      }
    }
  return pieces;
}

}  // namespace radmesh
