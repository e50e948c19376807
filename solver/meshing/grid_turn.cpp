#include "solver/meshing/grid_turn.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

namespace radmesh {

namespace {

// Edges within half a degree of a direction count as along it: exported walls are that straight.
const double kAlongRadians = 0.5 * std::numbers::pi / 180.0;
// Directions are compared four times over, so that a quarter turn apart is the same.
const double kAlongQuadrupled = 4.0 * kAlongRadians;
// Of all the edge length, for a turn of its own: a wing, not tilted furniture (office3 has 14 % of
// its edges on chairs at 15 degrees about a level axis).
constexpr double kTurnShare = 0.25;
constexpr int kMaxTurns = 4;
// Directions an outline's own grid may take: those of its longest edges.
constexpr size_t kOwnCandidates = 8;
constexpr int kBins = 360;  // of the quadrupled direction: a quarter of a degree of direction each

double wrapped(double angle) { return std::remainder(angle, 2.0 * std::numbers::pi); }

bool squareTo(const Vec3& d, double length, int axis) { return std::abs(d[axis]) <= std::sin(kAlongRadians) * length; }
bool alongAxis(const Vec3& d, double length, int axis) { return std::abs(d[axis]) >= std::cos(kAlongRadians) * length; }
double quadrupledDirection(const Vec3& d, int axis) {
  return wrapped(4.0 * std::atan2(d[(axis + 2) % 3], d[(axis + 1) % 3]));
}

// An edge square to an axis, not along the world axes: its length and quadrupled direction.
struct Edge {
  double length;
  double quadrupled;
};

// The heaviest direction of the edges: the histogram's heaviest five bins, then the mean of the
// edges near them, which stray edges (a chair at an angle) do not pull.
double heaviestDirection(const std::vector<Edge>& edges) {
  std::array<double, kBins> bins{};
  const auto binOf = [](double quadrupled) {
    return static_cast<int>(std::floor((quadrupled + std::numbers::pi) / (2.0 * std::numbers::pi) * kBins)) % kBins;
  };
  for (const Edge& e : edges) bins[binOf(e.quadrupled)] += e.length;
  int peak = 0;
  double heaviest = -1.0;
  for (int b = 0; b < kBins; ++b) {
    double sum = 0.0;
    for (int k = -2; k <= 2; ++k) sum += bins[(b + k + kBins) % kBins];
    if (sum > heaviest) heaviest = sum, peak = b;
  }
  const double centre = wrapped((peak + 0.5) / kBins * 2.0 * std::numbers::pi - std::numbers::pi);
  double offset = 0.0, near = 0.0;
  for (const Edge& e : edges) {
    const double d = wrapped(e.quadrupled - centre);
    if (std::abs(d) > 3.0 * 2.0 * std::numbers::pi / kBins) continue;
    offset += e.length * d;
    near += e.length;
  }
  return wrapped(centre + offset / near);
}

// A direction turned by `radians` about a world axis, counter-clockwise seen from its tip.
Vec3 turnedAbout(const Vec3& d, int axis, double radians) {
  const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
  const double c = std::cos(radians), s = std::sin(radians);
  Vec3 out;
  out[axis] = d[axis];
  out[a1] = c * d[a1] - s * d[a2];
  out[a2] = s * d[a1] + c * d[a2];
  return out;
}

// The outline's edge length along the grid's axes: the turn's own axis, and the turned directions
// square to it (the world grid: any of the world axes). A tilted grid's are the axis it tilts about
// and the tilted directions, in its turned frame.
double lengthAlong(const std::vector<Vec3>& outline, const GridTurn* turn) {
  const bool tilted = turn && turn->tiltRadians != 0.0;
  const int axis = !turn ? 0 : tilted ? turn->tiltAxis : turn->axis;
  const double radians = !turn ? 0.0 : tilted ? turn->tiltRadians : turn->radians;
  double sum = 0.0;
  for (size_t i = 0; i < outline.size(); ++i) {
    const Vec3 world = outline[(i + 1) % outline.size()] - outline[i];
    const double length = glm::length(world);
    if (!(length > 0.0)) continue;
    const Vec3 d = tilted ? turnedAbout(world, turn->axis, -turn->radians) : world;
    if (!turn) {
      if (alongAxis(d, length, 0) || alongAxis(d, length, 1) || alongAxis(d, length, 2)) sum += length;
    } else if (alongAxis(d, length, axis) ||
               (squareTo(d, length, axis) &&
                std::abs(wrapped(quadrupledDirection(d, axis) - 4.0 * radians)) <= kAlongQuadrupled)) {
      sum += length;
    }
  }
  return sum;
}

// The corners of the outlines' box.
std::pair<Vec3, Vec3> boxOf(const std::vector<const std::vector<Vec3>*>& outlines) {
  Vec3 low(INFINITY), high(-INFINITY);
  for (const std::vector<Vec3>* outline : outlines)
    for (const Vec3& v : *outline) low = glm::min(low, v), high = glm::max(high, v);
  return {low, high};
}

// Along the axis it turns about a turned grid keeps the lines of the grid it turns from (`from`'s
// pivot: the world's, or for a tilted grid the turned one's). Across it, its lines pass through the
// corner of its outlines' box in its frame: outlines turned about any point mesh as themselves
// unturned with that corner at the origin. The corner is found about the outlines' middle, so that
// site coordinates keep their precision.
void placePivot(GridTurn& turn, const std::vector<const std::vector<Vec3>*>& outlines, const Vec3& from = Vec3(0.0)) {
  const int kept = turn.tiltRadians != 0.0 ? turn.tiltAxis : turn.axis;
  const auto [low, high] = boxOf(outlines);
  turn.pivot = (low + high) / 2.0;
  Vec3 corner(INFINITY);
  for (const std::vector<Vec3>* outline : outlines)
    for (const Vec3& v : *outline) corner = glm::min(corner, turn.toGrid(v));
  corner[kept] = turn.toGrid(from)[kept];
  turn.pivot = turn.toWorld(corner);
}

// The grid `base` tilted about one of its axes so that the outline lies flat on it, where its
// normal is square to that axis and along none of base's.
std::optional<GridTurn> tiltedFlat(const std::vector<Vec3>& outline, const GridTurn& base) {
  const Vec3 normal = base.directionToGrid(newellNormal(outline));
  const double length = glm::length(normal);
  if (!(length > 0.0)) return std::nullopt;
  for (int a = 0; a < 3; ++a) {
    if (!squareTo(normal, length, a)) continue;
    const double quadrupled = quadrupledDirection(normal, a);
    if (std::abs(quadrupled) <= kAlongQuadrupled) return std::nullopt;  // flat on base already
    GridTurn turn;
    turn.axis = base.turned() ? base.axis : a;
    turn.radians = base.turned() ? base.radians : quadrupled / 4.0;
    if (base.turned()) turn.tiltAxis = a, turn.tiltRadians = quadrupled / 4.0;
    return turn;
  }
  return std::nullopt;
}

// The outline's own grid, where it lies along more of it than `than` (along base, the grid it would
// go on): base tilted so that the outline lies flat on it, where it lies along as much of that;
// or of the directions of its longest edges square to a world axis (not along the world's), the
// one the most of its edge length lies along.
std::optional<GridTurn> ownGrid(const std::vector<Vec3>& outline, double than, const GridTurn& base) {
  struct Candidate {
    double length;
    GridTurn turn;
  };
  std::vector<Candidate> candidates;
  for (size_t i = 0; i < outline.size(); ++i) {
    const Vec3 d = outline[(i + 1) % outline.size()] - outline[i];
    const double length = glm::length(d);
    if (!(length > 0.0)) continue;
    for (int a = 0; a < 3; ++a) {
      if (!squareTo(d, length, a)) continue;
      const double quadrupled = quadrupledDirection(d, a);
      if (std::abs(quadrupled) > kAlongQuadrupled) candidates.push_back({length, {a, quadrupled / 4.0}});
    }
  }
  const size_t kept = std::min(candidates.size(), kOwnCandidates);
  std::partial_sort(candidates.begin(), candidates.begin() + static_cast<std::ptrdiff_t>(kept), candidates.end(),
                    [](const Candidate& x, const Candidate& y) { return x.length > y.length; });
  std::optional<GridTurn> best = tiltedFlat(outline, base);
  if (best) {
    const double m = lengthAlong(outline, &*best);
    if (m >= than)
      than = m;
    else
      best.reset();
  }
  for (size_t c = 0; c < kept; ++c) {
    const double m = lengthAlong(outline, &candidates[c].turn);
    if (m > than) than = m, best = candidates[c].turn;
  }
  if (best) best->own = true;
  return best;
}

}  // namespace

double GridTurn::degrees() const { return radians * 180.0 / std::numbers::pi; }

Vec3 GridTurn::directionToGrid(const Vec3& world) const {
  return turnedAbout(turnedAbout(world, axis, -radians), tiltAxis, -tiltRadians);
}

Vec3 GridTurn::directionToWorld(const Vec3& grid) const {
  return turnedAbout(turnedAbout(grid, tiltAxis, tiltRadians), axis, radians);
}

Vec3 GridTurn::toGrid(const Vec3& world) const { return directionToGrid(world - pivot); }

Vec3 GridTurn::toWorld(const Vec3& grid) const { return directionToWorld(grid) + pivot; }

const GridTurn& Grids::of(size_t outline) const { return turnOf[outline] < 0 ? world : turns[turnOf[outline]]; }

size_t Grids::outlinesOn(size_t turn) const {
  return static_cast<size_t>(std::count(turnOf.begin(), turnOf.end(), static_cast<int>(turn)));
}

size_t Grids::outlinesOnOwnGrids() const {
  return static_cast<size_t>(std::count_if(turns.begin(), turns.end(), [](const GridTurn& t) { return t.own; }));
}

GridTurn Grids::principal() const {
  GridTurn best;
  double bestM = worldEdgeM;
  for (size_t t = 0; t < turns.size(); ++t)
    if (!turns[t].own && edgeM[t] > bestM) best = turns[t], bestM = edgeM[t];
  return best;
}

Grids gridsOf(const Scene& scene) {
  std::vector<const std::vector<Vec3>*> outlines;
  outlines.reserve(scene.polygons.size());
  for (const Polygon& polygon : scene.polygons) outlines.push_back(&polygon.vertices);
  return gridsOf(outlines);
}

Grids gridsOf(const std::vector<const std::vector<Vec3>*>& outlines) {
  // Edges square to each axis, not along the world axes.
  std::array<std::vector<Edge>, 3> edges;
  double allEdges = 0.0;
  for (const std::vector<Vec3>* outline : outlines)
    for (size_t i = 0; i < outline->size(); ++i) {
      const Vec3 d = (*outline)[(i + 1) % outline->size()] - (*outline)[i];
      const double length = glm::length(d);
      if (!(length > 0.0)) continue;
      allEdges += length;
      for (int a = 0; a < 3; ++a) {
        if (!squareTo(d, length, a)) continue;
        const double quadrupled = quadrupledDirection(d, a);
        if (std::abs(quadrupled) > kAlongQuadrupled) edges[a].push_back({length, quadrupled});
      }
    }

  // The turns, heaviest first, each taking its edges away from the next search.
  Grids grids;
  for (int a = 0; a < 3; ++a)
    while (!edges[a].empty() && static_cast<int>(grids.turns.size()) < kMaxTurns) {
      const double quadrupled = heaviestDirection(edges[a]);
      const auto along = [&](const Edge& e) { return std::abs(wrapped(e.quadrupled - quadrupled)) <= kAlongQuadrupled; };
      double alongM = 0.0;
      for (const Edge& e : edges[a]) alongM += along(e) ? e.length : 0.0;
      if (alongM < kTurnShare * allEdges) break;
      GridTurn turn;
      turn.axis = a;
      turn.radians = quadrupled / 4.0;
      grids.turns.push_back(turn);
      std::erase_if(edges[a], along);
    }

  // Each outline on the grid most of its edge length lies along, or on its own (ownGrid); turns
  // no outline takes go.
  const size_t modelTurns = grids.turns.size();
  grids.turnOf.assign(outlines.size(), -1);
  std::vector<double> edgeM(modelTurns, 0.0);
  for (size_t i = 0; i < outlines.size(); ++i) {
    double best = lengthAlong(*outlines[i], nullptr);
    for (size_t t = 0; t < modelTurns; ++t) {
      const double m = lengthAlong(*outlines[i], &grids.turns[t]);
      if (m > best) best = m, grids.turnOf[i] = static_cast<int>(t);
    }
    const GridTurn& base = grids.turnOf[i] < 0 ? grids.world : grids.turns[grids.turnOf[i]];
    if (const std::optional<GridTurn> own = ownGrid(*outlines[i], best, base)) {
      grids.turnOf[i] = static_cast<int>(grids.turns.size());
      grids.turns.push_back(*own);
      edgeM.push_back(lengthAlong(*outlines[i], &*own));
    } else {
      (grids.turnOf[i] < 0 ? grids.worldEdgeM : edgeM[grids.turnOf[i]]) += best;
    }
  }
  std::vector<int> kept(grids.turns.size(), -1);
  std::vector<GridTurn> turns;
  for (size_t t = 0; t < grids.turns.size(); ++t)
    if (edgeM[t] > 0.0 || grids.turns[t].own) {  // an own grid has its outline, along it or not
      kept[t] = static_cast<int>(turns.size());
      turns.push_back(grids.turns[t]);
      grids.edgeM.push_back(edgeM[t]);
    }
  grids.turns = std::move(turns);
  for (int& t : grids.turnOf) t = t < 0 ? -1 : kept[t];

  // The pivots: the model's turns' first, since a grid tilted from one keeps its lines along the
  // axis it tilts about.
  std::vector<std::vector<const std::vector<Vec3>*>> on(grids.turns.size());
  for (size_t i = 0; i < outlines.size(); ++i)
    if (grids.turnOf[i] >= 0) on[grids.turnOf[i]].push_back(outlines[i]);
  for (size_t t = 0; t < grids.turns.size(); ++t)
    if (!grids.turns[t].own) placePivot(grids.turns[t], on[t]);
  for (size_t t = 0; t < grids.turns.size(); ++t) {
    GridTurn& own = grids.turns[t];
    if (!own.own) continue;
    // A tilted grid's turn is its model turn's, copied (tiltedFlat).
    const auto from = std::find_if(grids.turns.begin(), grids.turns.end(), [&](const GridTurn& m) {
      return !m.own && own.tiltRadians != 0.0 && m.axis == own.axis && m.radians == own.radians;
    });
    placePivot(own, on[t], from != grids.turns.end() ? from->pivot : Vec3(0.0));
  }

  // Far: the origin lies beyond the model's box grown by its size on every side.
  const auto [low, high] = boxOf(outlines);
  const Vec3 size = high - low;
  const double grown = std::max({size.x, size.y, size.z});
  if (!outlines.empty() && glm::any(glm::greaterThan(low - grown, Vec3(0.0)) || glm::lessThan(high + grown, Vec3(0.0))))
    grids.world.pivot = low;
  return grids;
}

GridTurn gridTurnOf(const Scene& scene) { return gridsOf(scene).principal(); }

GridTurn gridTurnOf(const std::vector<const std::vector<Vec3>*>& outlines) { return gridsOf(outlines).principal(); }

}  // namespace radmesh
