#include "solver/cells/find_cells.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>

#include "solver/cells/cell_portals.h"
#include "solver/cells/voxel_grid.h"
#include "solver/cells/cell_of_patch.h"

namespace radmesh {

namespace {

// docs/cells.md explains the method: free space voxelised, eroded by a cube so that narrow
// openings close, its connected parts the rooms' cores (those touching the grid's border: the
// outside), grown back over free space breadth-first, and each place two cells meet turned into
// the exact rectangle of the opening there (cell_portals.cpp).
constexpr double kCutRadiusM = 0.6;  // openings less than about twice this wide are cut: doors, windows
constexpr double kVoxelM = kCutRadiusM / 4;
constexpr double kMaxVoxels = 24e6;  // bounds the memory at about 6 bytes a voxel

constexpr int kOutsideHandicap = 6;  // layers: where cell and outside meet moves 3 voxels outward

std::pair<Vec3, Vec3> boundsOf(const Patch& p) {
  Vec3 lo(kInf), hi(-kInf);
  for (int k = 0; k < p.vertexCount; ++k) {
    lo = glm::min(lo, p.vertices[k]);
    hi = glm::max(hi, p.vertices[k]);
  }
  return {lo, hi};
}

std::pair<Vec3, Vec3> boundsOf(const std::vector<Patch>& patches) {
  Vec3 lo(kInf), hi(-kInf);
  for (const Patch& p : patches) {
    const auto [a, b] = boundsOf(p);
    lo = glm::min(lo, a);
    hi = glm::max(hi, b);
  }
  return {lo, hi};
}

// The grid over the patches' bounds with `pad` free voxels around, its voxel enlarged from
// kVoxelM only where the building would take more than kMaxVoxels.
VoxelGrid makeGrid(const std::vector<Patch>& patches, int& pad) {
  const auto [lo, hi] = boundsOf(patches);
  VoxelGrid g;
  const Vec3 size = hi - lo;
  g.voxel = std::max(kVoxelM, std::cbrt(size.x * size.y * size.z / kMaxVoxels));
  pad = int(std::ceil(kCutRadiusM / g.voxel - 1e-9)) + 2;
  g.origin = lo - double(pad) * g.voxel;
  for (int a = 0; a < 3; ++a) g.n[a] = int(std::ceil(size[a] / g.voxel - 1e-9)) + 2 * pad;
  return g;
}

// Separating-axis test of a convex patch against the box lo..hi; touching counts as overlapping.
bool patchTouchesBox(const Patch& p, const Vec3& lo, const Vec3& hi) {
  const Vec3 centre = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  const double slack = 1e-9;
  auto separates = [&](const Vec3& axis) {
    double mn = kInf, mx = -kInf;
    for (int k = 0; k < p.vertexCount; ++k) {
      const double d = glm::dot(axis, p.vertices[k] - centre);
      mn = std::min(mn, d);
      mx = std::max(mx, d);
    }
    const double r = glm::dot(half, glm::abs(axis)) + slack;
    return mn > r || mx < -r;
  };
  if (separates(p.normal)) return false;
  for (int k = 0; k < p.vertexCount; ++k) {
    const Vec3 edge = p.vertices[(k + 1) % p.vertexCount] - p.vertices[k];
    for (int a = 0; a < 3; ++a) {
      Vec3 unit(0.0);
      unit[a] = 1.0;
      const Vec3 axis = glm::cross(edge, unit);
      if (glm::dot(axis, axis) > 1e-24 && separates(axis)) return false;
    }
  }
  return true;
}

std::vector<std::uint8_t> voxelise(const VoxelGrid& g, const std::vector<Patch>& patches) {
  std::vector<std::uint8_t> solid(g.size(), 0);
  for (const Patch& p : patches) {
    const auto [lo, hi] = boundsOf(p);
    const double e = 1e-9;
    const Index3 a = g.voxelOf(lo - Vec3(e)), b = g.voxelOf(hi + Vec3(e));
    for (int z = a[2]; z <= b[2]; ++z)
      for (int y = a[1]; y <= b[1]; ++y)
        for (int x = a[0]; x <= b[0]; ++x) {
          const Index3 v{x, y, z};
          const long i = g.index(v);
          if (!solid[i] && patchTouchesBox(p, g.corner(v), g.corner({x + 1, y + 1, z + 1}))) solid[i] = 1;
        }
  }
  return solid;
}

// `mask` grown by r voxels along `axis` (one pass of a cube dilation).
void dilateAlong(const VoxelGrid& g, std::vector<std::uint8_t>& mask, int axis, int r) {
  const long stride = g.stride(axis);
  const int length = g.n[axis], u = (axis + 1) % 3, w = (axis + 2) % 3;
  std::vector<std::uint8_t> line(length);
  for (int j = 0; j < g.n[w]; ++j)
    for (int i = 0; i < g.n[u]; ++i) {
      const long start = i * g.stride(u) + j * g.stride(w);
      for (int k = 0; k < length; ++k) line[k] = mask[start + k * stride];
      for (int direction : {1, -1}) {
        int since = r + 1;  // voxels since the last set one
        for (int k = direction > 0 ? 0 : length - 1; k >= 0 && k < length; k += direction) {
          since = line[k] ? 0 : since + 1;
          if (since <= r) mask[start + k * stride] = 1;
        }
      }
    }
}

// The six face neighbours of voxel i that lie in the grid.
template <class F>
void forNeighbours(const VoxelGrid& g, long i, F&& f) {
  const Index3 v = g.coords(i);
  for (int a = 0; a < 3; ++a) {
    if (v[a] > 0) f(i - g.stride(a));
    if (v[a] + 1 < g.n[a]) f(i + g.stride(a));
  }
}


// Cores: the connected parts of the eroded free space, outside those touching the border; then
// every free voxel takes the label of the core nearest to it (breadth-first, 6-connected).
VoxelLabels labelVoxels(const VoxelGrid& g, const std::vector<std::uint8_t>& solid, int radius) {
  std::vector<std::uint8_t> blocked = solid;
  for (int a = 0; a < 3; ++a) dilateAlong(g, blocked, a, radius);
  VoxelLabels out;
  out.label.assign(g.size(), kUnreached);
  for (long i = 0; i < g.size(); ++i)
    if (solid[i]) out.label[i] = kSolid;
  std::vector<long> queue;
  std::vector<long> seeds;
  for (long start = 0; start < g.size(); ++start) {
    if (blocked[start] || out.label[start] != kUnreached) continue;
    queue.assign(1, start);
    out.label[start] = out.cells;
    bool border = false;
    for (size_t head = 0; head < queue.size(); ++head) {
      const Index3 v = g.coords(queue[head]);
      for (int a = 0; a < 3; ++a) border = border || v[a] == 0 || v[a] + 1 == g.n[a];
      forNeighbours(g, queue[head], [&](long j) {
        if (!blocked[j] && out.label[j] == kUnreached) {
          out.label[j] = out.cells;
          queue.push_back(j);
        }
      });
    }
    if (border)
      for (long i : queue) out.label[i] = kOutsideCell;
    else
      ++out.cells;
    seeds.insert(seeds.end(), queue.begin(), queue.end());
  }
  // Grown a layer at a time from the cores in the order found, so that ties go the same way every
  // time (to the lower cell); the cells kOutsideHandicap layers ahead of the outside, so that the
  // passage of a window belongs to its room.
  std::vector<long> frontier, outside;
  for (long i : seeds) (out.label[i] == kOutsideCell ? outside : frontier).push_back(i);
  for (int layer = 0; !frontier.empty() || !outside.empty(); ++layer) {
    if (layer == kOutsideHandicap) {
      frontier.insert(frontier.end(), outside.begin(), outside.end());
      outside.clear();
    }
    std::vector<long> next;
    for (long i : frontier) {
      const std::int32_t l = out.label[i];
      forNeighbours(g, i, [&](long j) {
        if (out.label[j] == kUnreached) {
          out.label[j] = l;
          next.push_back(j);
        }
      });
    }
    frontier = std::move(next);
  }
  return out;
}

// The group holding most of each cell's patch area, "" for a cell with none.
std::vector<std::string> mainGroups(const Scene& scene, const std::vector<Patch>& patches,
                                    const std::vector<int>& cellOfPatch, int cells) {
  std::vector<std::map<std::string, double>> area(cells);
  for (size_t i = 0; i < patches.size(); ++i) {
    const std::string group = groupOfOrigin(scene.polygons[patches[i].polygon].origin);
    if (cellOfPatch[i] >= 0 && !group.empty()) area[cellOfPatch[i]][group] += patches[i].areaM2;
  }
  std::vector<std::string> out(cells);
  for (int c = 0; c < cells; ++c) {
    double most = 0.0;
    for (const auto& [group, a] : area[c])
      if (a > most) {
        most = a;
        out[c] = group;
      }
  }
  return out;
}

// Cells with the same main group made one (at the first one's place in the order, its bounds
// grown to hold them all), the portals between them dropped.
void joinByGroup(CellPartition& p, const std::vector<std::string>& group) {
  std::vector<int> to(p.cells.size());
  std::map<std::string, int> first;
  std::vector<Cell> cells;
  for (size_t c = 0; c < p.cells.size(); ++c) {
    const auto it = group[c].empty() ? first.end() : first.find(group[c]);
    if (it == first.end()) {
      to[c] = int(cells.size());
      if (!group[c].empty()) first[group[c]] = to[c];
      cells.push_back(p.cells[c]);
      continue;
    }
    to[c] = it->second;
    Cell& joined = cells[to[c]];
    joined.boundsMin = glm::min(joined.boundsMin, p.cells[c].boundsMin);
    joined.boundsMax = glm::max(joined.boundsMax, p.cells[c].boundsMax);
  }
  for (int& c : p.cellOfPatch)
    if (c >= 0) c = to[c];
  std::vector<Portal> portals;
  for (Portal q : p.portals) {
    q.cellA = to[q.cellA];
    q.cellB = to[q.cellB];
    if (q.cellA == q.cellB) continue;
    if (q.cellA > q.cellB) {  // keep cellA the lower, the normal pointing into cellB
      std::swap(q.cellA, q.cellB);
      std::reverse(q.vertices.begin(), q.vertices.end());
    }
    portals.push_back(std::move(q));
  }
  p.cells = std::move(cells);
  p.portals = std::move(portals);
}

// The inside of a solid object (a closed box of outward faces) is enclosed space that no patch
// faces: no room, and a cell of no patches that no solve could take. Dropped with any portal to it.
void dropCellsNoPatchFaces(CellPartition& p, std::vector<std::string>& group) {
  std::vector<int> faced(p.cells.size(), 0);
  for (int c : p.cellOfPatch)
    if (c >= 0) faced[c] = 1;
  if (std::find(faced.begin(), faced.end(), 1) == faced.end()) return;  // nothing to keep them apart
  std::vector<int> to(p.cells.size(), -1);
  std::vector<Cell> cells;
  std::vector<std::string> groups;
  for (size_t c = 0; c < p.cells.size(); ++c)
    if (faced[c]) to[c] = int(cells.size()), cells.push_back(p.cells[c]), groups.push_back(group[c]);
  for (int& c : p.cellOfPatch)
    if (c >= 0) c = to[c];
  std::vector<Portal> portals;
  for (Portal q : p.portals)
    if (to[q.cellA] >= 0 && to[q.cellB] >= 0) q.cellA = to[q.cellA], q.cellB = to[q.cellB], portals.push_back(std::move(q));
  p.cells = std::move(cells);
  p.portals = std::move(portals);
  group = std::move(groups);
}

}  // namespace

std::string groupOfOrigin(const std::string& origin) {
  for (const std::string& key : {std::string("room '"), std::string("(object '")}) {
    const auto at = origin.find(key);
    if (at == std::string::npos) continue;
    const auto begin = at + key.size();
    const auto end = origin.find_first_of("'/", begin);
    if (end != std::string::npos && end > begin) return origin.substr(begin, end - begin);
  }
  return "";
}

CellPartition findCells(const Scene& scene, const std::vector<Patch>& patches) {
  return findCells(scene, patches, CellGroups::Name);
}

CellPartition findCells(const Scene& scene, const std::vector<Patch>& patches, CellGroups groups) {
  CellPartition out;
  if (patches.empty()) return out;
  int pad = 0;
  const VoxelGrid g = makeGrid(patches, pad);
  const int radius = pad - 2;
  const VoxelLabels labels = labelVoxels(g, voxelise(g, patches), radius);

  const int cells = std::max(labels.cells, 1);  // no enclosed room at all: the whole scene is one
  const ScenePolygons polys(scene);
  if (labels.cells > 0) out.portals = findPortals(g, labels, polys, radius);
  out.cellOfPatch = labels.cells == 0 ? std::vector<int>(patches.size(), 0)
                                       : cellsFaced(g, labels, polys, out.portals, patches, 2 * radius);

  out.cells.resize(cells);
  std::vector<Vec3> lo(cells, Vec3(kInf)), hi(cells, Vec3(-kInf));
  long i = 0;
  for (int z = 0; z < g.n[2]; ++z)
    for (int y = 0; y < g.n[1]; ++y)
      for (int x = 0; x < g.n[0]; ++x, ++i) {
        const std::int32_t l = labels.label[i];
        if (l < 0) continue;
        const Vec3 corner = g.corner({x, y, z});
        lo[l] = glm::min(lo[l], corner);
        hi[l] = glm::max(hi[l], corner + g.voxel);
      }
  if (labels.cells == 0) std::tie(lo[0], hi[0]) = boundsOf(patches);  // the scene's bounds
  std::vector<std::string> group = mainGroups(scene, patches, out.cellOfPatch, cells);
  std::map<std::string, int> used;
  for (int c = 0; c < cells; ++c) {
    const bool named = !group[c].empty() && used[group[c]]++ == 0;
    out.cells[c] = {named ? group[c] : "", lo[c], hi[c]};
  }
  dropCellsNoPatchFaces(out, group);
  for (size_t c = 0; c < out.cells.size(); ++c)
    if (out.cells[c].name.empty()) out.cells[c].name = "cell " + std::to_string(c);
  if (groups == CellGroups::Join) joinByGroup(out, group);
  return out;
}

}  // namespace radmesh
