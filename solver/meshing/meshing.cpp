#include "solver/meshing/meshing.h"

#include <fmt/core.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "solver/geometry/polygon_clip.h"
#include "solver/geometry/polygon_convex.h"
#include "solver/meshing/grid_turn.h"
#include "solver/scene/scene_error.h"
#include "solver/scene/solve_options.h"

namespace radmesh {

namespace {

// A polygon's own 2D frame: world axes u and v span its dominant plane (ordered so that the
// polygon is counter-clockwise in them), n is the dropped one. Coordinates are taken relative to a
// grid corner near the polygon, so the global grid lines fall at integer multiples of the cell and
// a scene far from the world origin keeps its precision.
struct PolygonFrame {
  int u = 0, v = 1, n = 2;
  Vec3 origin{0.0};  // a grid corner in u and v; the plane's height in n
  Vec3 unitNormal{0.0};
  Vec2 planePoint{0.0};      // a point of the plane (local u, v) ...
  double planeHeight = 0.0;  // ... and its local n coordinate

  Vec2 toLocal(const Vec3& p) const { return {p[u] - origin[u], p[v] - origin[v]}; }

  // Back onto the polygon's plane (its mean plane, if the input is slightly bent), in world space.
  Vec3 lift(const Vec2& q) const {
    const Vec2 d = q - planePoint;
    Vec3 world;
    world[u] = origin[u] + q.x;
    world[v] = origin[v] + q.y;
    world[n] = origin[n] + planeHeight - (unitNormal[u] * d.x + unitNormal[v] * d.y) / unitNormal[n];
    return world;
  }
};

// One polygon cut into convex pieces, in its own frame, before slicing.
struct PreparedPolygon {
  PolygonFrame frame;  // in the grid's frame: the world's unless the grid is turned
  GridTurn turn;
  Vec3 worldNormal{0.0};
  Frame patchFrame;
  std::vector<std::vector<Vec2>> pieces;
  double noiseM = 0.0;        // distances below this are rounding, not geometry
  double sliverAreaM2 = 0.0;  // projected area below which a piece is a clipping sliver
};

// The projection frame of section 1.5: n is the normal, u the world axis least aligned with it,
// projected into the plane (deterministic, and the same for every patch of a polygon).
Frame frameFor(const Vec3& normal) {
  const auto [u, v] = perpendicularAxes(normal);
  return {u, v, normal};
}

PreparedPolygon prepare(const Scene& scene, size_t index, double cellM, const GridTurn& turn) {
  const std::vector<Vec3>& worldVertices = scene.polygons[index].vertices;
  const Vec3 worldNewell = newellNormal(worldVertices);
  const double length = glm::length(worldNewell);
  if (worldVertices.size() < 3 || !(length > 0.0) || !std::isfinite(length))
    throw SceneError(scene.source, polygonName(scene, index), "has zero or non-finite area",
                     "remove the polygon or fix its vertices");
  std::vector<Vec3> turned;
  if (turn.moved())
    for (const Vec3& p : worldVertices) turned.push_back(turn.toGrid(p));
  const std::vector<Vec3>& vertices = turn.moved() ? turned : worldVertices;
  const Vec3 newell = turn.turned() ? newellNormal(vertices) : worldNewell;
  PreparedPolygon out;
  out.turn = turn;
  out.worldNormal = worldNewell / length;
  PolygonFrame& f = out.frame;
  f.unitNormal = newell / glm::length(newell);
  for (int k = 0; k < 3; ++k)
    if (std::abs(newell[k]) > std::abs(newell[f.n])) f.n = k;
  // Newell's n-component is twice the signed area projected along n: order u, v to make it positive.
  f.u = (f.n + (newell[f.n] > 0 ? 1 : 2)) % 3;
  f.v = (f.n + (newell[f.n] > 0 ? 2 : 1)) % 3;
  double maxAbs = 0.0;
  Vec3 lo = vertices[0];
  for (const Vec3& p : vertices) {
    lo = glm::min(lo, p);
    maxAbs = std::max({maxAbs, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  }
  f.origin[f.u] = std::floor(lo[f.u] / cellM) * cellM;
  f.origin[f.v] = std::floor(lo[f.v] / cellM) * cellM;
  f.origin[f.n] = vertices[0][f.n];
  std::vector<Vec2> points;
  Vec3 mean{0.0};
  for (const Vec3& p : vertices) {
    points.push_back(f.toLocal(p));
    mean += p - f.origin;
  }
  mean /= static_cast<double>(vertices.size());
  f.planePoint = {mean[f.u], mean[f.v]};
  f.planeHeight = mean[f.n];
  // On a turned grid the projection frame turns with it: a model's shots do not depend on its turn.
  const Frame grid = frameFor(f.unitNormal);
  out.patchFrame = turn.turned()
                       ? Frame{turn.directionToWorld(grid.u), turn.directionToWorld(grid.v), out.worldNormal}
                       : frameFor(out.worldNormal);

  // Rounding noise: relative to the polygon's size, and to the magnitude of its world coordinates.
  out.noiseM = 1e-12 * extentOf(points) + 4.0 * DBL_EPSILON * maxAbs;
  const double area = signedArea(points);
  out.sliverAreaM2 = 1e-12 * area;
  std::string crossing;
  out.pieces = convexCover(points, out.noiseM, crossing);
  if (!crossing.empty())
    throw SceneError(scene.source, polygonName(scene, index), "crosses or overlaps itself (" + crossing + ")",
                     "split it into simple polygons");
  return out;
}

// Grid cells a convex piece touches, from above: the cells of its bounding box, or (for a thin
// slanted piece) its area grown by one cell along each side of the box.
double cellEstimate(const std::vector<Vec2>& piece, double cellM, double noiseM) {
  Vec2 lo = piece[0], hi = piece[0];
  for (const Vec2& p : piece) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const auto span = [&](int a) {
    return std::max(1.0, std::ceil((hi[a] - noiseM) / cellM) - std::floor((lo[a] + noiseM) / cellM));
  };
  const Vec2 size = hi - lo;
  const double grown = signedArea(piece) / (cellM * cellM) + (size.x + size.y) / cellM + 1.0;
  return std::min(span(0) * span(1), grown);
}

}  // namespace

void checkCell(double cellM) {
  if (!std::isfinite(cellM) || !(cellM > 0.0))
    throw OptionError(fmt::format(
        "--cell must be a finite grid size in metres greater than 0, got {}; use e.g. --cell 0.381 "
        "(15 inches, the paper's grid)",
        cellM));
}

namespace {

// The cell at which about `patches` at `cellM` fall to 90 % of the limit, by the estimate's own
// shape: a piece's cells are its area / cell^2 plus its sides / cell plus one, so the count goes as
// area / c^2 + sides / c + pieces, with the sides found from the count at cellM. Not a number where
// the pieces alone pass 90 % of the limit.
double fittingCell(double patches, double cellM, double limit, double areaM2, double pieces) {
  const double sides = std::max(0.0, (patches - areaM2 / (cellM * cellM) - pieces) * cellM);
  const double room = 0.9 * limit - pieces;
  if (!(room > 0.0)) return NAN;
  // area x^2 + sides x - room = 0, x = 1 / c: the positive root.
  const double x = 2.0 * room / (sides + std::sqrt(sides * sides + 4.0 * areaM2 * room));
  return std::max(1.0 / x, cellM);
}

void refuseCount(double patches, double cellM, size_t maxPatches, double areaM2, size_t polygons) {
  const double limit = static_cast<double>(maxPatches);
  const std::string count =
      std::isfinite(patches) ? fmt::format("about {:.3g}", patches) : "uncountably many";
  const double pieces = static_cast<double>(polygons);
  const double suggested = std::isfinite(patches) ? fittingCell(patches, cellM, limit, areaM2, pieces)
                                                  : 2.0 * std::sqrt(areaM2 / limit);
  // Where the polygons alone are most of the limit, a larger cell fits only by making each polygon
  // about one patch, which resolves no light on it.
  const std::string fix =
      !(pieces <= 0.5 * limit) || !std::isfinite(suggested)
          ? fmt::format("its {} polygons alone are {:.0f} % of the limit, so no cell leaves them more than about one "
                        "patch each; solve a smaller model (a wing or a floor a file; building:COLSxROWS with fewer "
                        "rooms)",
                        polygons, 100.0 * pieces / limit)
          : fmt::format("use a larger --cell (about {:.3g} m or more)", suggested);
  throw OptionError(fmt::format("the cell {:.4g} m would cut the scene into {} patches, more than the limit of {}; {}",
                                cellM, count, maxPatches, fix));
}

// Drops repeated and collinear vertices (within noise): what is left turns strictly left.
std::vector<Vec2> withoutStraightVertices(std::vector<Vec2> p, double noiseM) {
  for (bool changed = true; changed && p.size() >= 3;) {
    changed = false;
    for (size_t i = 0; i < p.size() && p.size() >= 3; ++i) {
      const Vec2& a = p[(i + p.size() - 1) % p.size()];
      const Vec2& c = p[(i + 1) % p.size()];
      if (glm::length(p[i] - a) <= noiseM || std::abs(sideOfLine(a, c, p[i])) <= noiseM) {
        p.erase(p.begin() + static_cast<long>(i));
        changed = true;
      }
    }
  }
  return p;
}

// Fanning from the lowest vertex (x, then y) makes the patches independent of which vertex the
// input polygon happened to list first.
void startAtLowestVertex(std::vector<Vec2>& p) {
  const auto lower = [](const Vec2& a, const Vec2& b) { return a.x != b.x ? a.x < b.x : a.y < b.y; };
  std::rotate(p.begin(), std::min_element(p.begin(), p.end(), lower), p.end());
}

Patch makePatch(const PreparedPolygon& prepared, const std::vector<Vec2>& q, double area2d, int material,
                int polygon) {
  const GridTurn& turn = prepared.turn;
  const PolygonFrame& f = prepared.frame;
  Patch patch;
  patch.vertexCount = static_cast<int>(q.size());
  Vec2 centroid{0.0};
  for (size_t i = 1; i + 1 < q.size(); ++i)
    centroid += cross2(q[i] - q[0], q[i + 1] - q[0]) * (q[0] + q[i] + q[i + 1]) / 3.0;
  centroid = centroid / (2.0 * area2d);
  const auto world = [&](const Vec2& p) { return turn.moved() ? turn.toWorld(f.lift(p)) : f.lift(p); };
  for (size_t i = 0; i < q.size(); ++i) patch.vertices[i] = world(q[i]);
  // Lifting onto the plane and turning are affine, so they carry the area centroid along; areas
  // grow by 1 / cos of the angle between the normal and the dropped axis.
  patch.centroid = world(centroid);
  patch.areaM2 = area2d / std::abs(f.unitNormal[f.n]);
  patch.normal = prepared.worldNormal;
  patch.frame = prepared.patchFrame;
  patch.material = material;
  patch.polygon = polygon;
  return patch;
}

// How many patches the cell makes, from above (cellEstimate), each polygon prepared for it;
// `prepared` and `areaM2` (the pieces' projected area) are filled when given.
double patchEstimate(const Scene& scene, double cellM, const Grids& grids,
                     std::vector<PreparedPolygon>* prepared = nullptr, double* areaM2 = nullptr) {
  if (prepared) prepared->reserve(scene.polygons.size());
  double estimate = 0.0;
  for (size_t i = 0; i < scene.polygons.size(); ++i) {
    PreparedPolygon p = prepare(scene, i, cellM, grids.of(i));
    for (const auto& piece : p.pieces) {
      estimate += cellEstimate(piece, cellM, p.noiseM);
      if (areaM2) *areaM2 += signedArea(piece);
    }
    if (prepared) prepared->push_back(std::move(p));
  }
  return estimate;
}

}  // namespace

std::vector<Patch> meshScene(const Scene& scene, double cellM, size_t maxPatches) {
  checkCell(cellM);
  // A cell holds at most cell^2 of area: a cell so small that the area alone passes the limit is
  // refused before the polygons are laid on its grid, where coordinates over it would overflow.
  const double sceneAreaM2 = totalArea(scene.polygons);
  if (!(sceneAreaM2 / (cellM * cellM) <= static_cast<double>(maxPatches)))
    refuseCount(sceneAreaM2 / (cellM * cellM), cellM, maxPatches, sceneAreaM2, scene.polygons.size());
  std::vector<PreparedPolygon> prepared;
  double areaM2 = 0.0;
  const double estimate = patchEstimate(scene, cellM, gridsOf(scene), &prepared, &areaM2);
  // Refuse before slicing: a tiny cell must fail fast, not exhaust memory.
  if (!(estimate <= static_cast<double>(maxPatches)))
    refuseCount(estimate, cellM, maxPatches, areaM2, scene.polygons.size());

  std::vector<Patch> patches;
  patches.reserve(static_cast<size_t>(estimate));
  for (size_t i = 0; i < prepared.size(); ++i) {
    const PreparedPolygon& p = prepared[i];
    for (const auto& piece : p.pieces) {
      for (const auto& cell : sliceByGrid(piece, cellM, p.noiseM)) {
        std::vector<Vec2> clean = withoutStraightVertices(cell, p.noiseM);
        if (clean.size() < 3) continue;
        startAtLowestVertex(clean);
        for (const auto& q : fanIntoQuads(clean)) {
          const double area2d = signedArea(q);
          if (!(area2d > p.sliverAreaM2)) continue;  // a zero-area sliver of clipping
          if (patches.size() >= maxPatches)
            refuseCount(std::max(estimate, maxPatches + 1.0), cellM, maxPatches, areaM2, scene.polygons.size());
          patches.push_back(makePatch(p, q, area2d, scene.polygons[i].material, static_cast<int>(i)));
        }
      }
    }
  }
  return patches;
}

CellChoice elementsPresetChoice(const CellChoice& sceneCell) {
  const double cellM = elementsPresetCell(sceneCell.cellM);
  return {cellM, fmt::format("cell {:.4g} m, --preset elements' {:.4g} x the scene's, rounded: {}", cellM,
                             kElementsCellScale, sceneCell.why)};
}

namespace {

// The cell that makes at most about `budget` patches of the scene's area, no finer than `finest`.
// Polygons narrower than the cell make partial patches, many more than area / cell^2 (a
// building's walls: three times as many): the cell grows until the count itself fits. The
// estimate is from above: "about" allows it a quarter over. Where the polygons alone are most of
// the count, a larger cell stops helping: the cell stays where it did.
CellChoice cellWithinBudget(const Scene& scene, double areaM2, double budget, double finest) {
  double cellM = std::max(finest, std::sqrt(areaM2 / budget));
  const Grids grids = gridsOf(scene);
  double estimate = patchEstimate(scene, cellM, grids);
  for (int step = 0; step < 20 && estimate > 1.25 * budget; ++step) {
    const double grown = cellM * std::min(2.0, estimate / budget);
    const double fewer = patchEstimate(scene, grown, grids);
    if (fewer > 0.9 * estimate) break;
    cellM = grown;
    estimate = fewer;
  }
  if (estimate > 1.25 * budget)
    return {cellM, fmt::format("cell {:.4g} m: its {} polygons alone make more than {:.0f} patches (about {:.3g} "
                               "here; a larger cell hardly lowers that)",
                               cellM, scene.polygons.size(), budget, estimate)};
  return {cellM, fmt::format("cell {:.4g} m, so that its {:.4g} m^2 make at most about {:.0f} patches", cellM,
                             areaM2, budget)};
}

}  // namespace

CellChoice chooseCell(const Scene& scene) {
  Vec3 low(DBL_MAX), high(-DBL_MAX);
  double area = 0.0;
  for (const Polygon& p : scene.polygons) {
    area += polygonArea(p.vertices);
    for (const Vec3& v : p.vertices) {
      low = glm::min(low, v);
      high = glm::max(high, v);
    }
  }
  if (scene.polygons.empty()) return {kDefaultCellM, "the paper's 15-inch cell"};
  // The smallest extent that is not flat: a single wall is sized by its shorter side.
  const Vec3 extent = high - low;
  const double largest = std::max({extent.x, extent.y, extent.z});
  double smallest = largest;
  for (int a = 0; a < 3; ++a)
    if (extent[a] > 1e-9 * largest) smallest = std::min(smallest, extent[a]);
  const double budgetCell = std::sqrt(area / kCellPatchBudget);
  // A model narrower than a room is cut finer, but a long one (a 1000 m corridor 1 m wide) within
  // the budget all the same; an object smaller than a room in every direction (a luminaire
  // 1.2 x 0.26 x 0.09 m) within a room's count of patches, or its thinnest side would make it
  // ten times a room's and minutes of solving.
  const bool narrow = smallest < kRoomSizedM;
  const double sixteenth = smallest / 16.0;
  if (narrow && largest < kRoomSizedM) {
    const CellChoice object = cellWithinBudget(scene, area, kObjectPatchBudget, sixteenth);
    if (object.cellM > sixteenth)
      return {object.cellM, fmt::format("{} (an object smaller than a room: a sixteenth of its smallest extent, "
                                        "{:.3g} m, would make more)", object.why, smallest)};
  }
  if (narrow && sixteenth >= budgetCell)
    return {sixteenth, fmt::format("cell {:.4g} m, a sixteenth of the model's smallest extent ({:.3g} m, "
                                   "smaller than a room)", sixteenth, smallest)};
  if (narrow || budgetCell > kDefaultCellM) return cellWithinBudget(scene, area, kCellPatchBudget, 0.0);
  return {kDefaultCellM, fmt::format("cell {} m, the paper's 15 inches (a room-sized model)", kDefaultCellM)};
}

}  // namespace radmesh
