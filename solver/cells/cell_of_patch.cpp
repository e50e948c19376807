#include "solver/cells/cell_of_patch.h"

#include <array>
#include <cmath>

#include "solver/meshing/occluders.h"

namespace radmesh {

namespace {

// The cell on x's side of the portal's plane where x is within `reach` of the portal (the rectangle
// findPortals makes, grown by reach in its plane), else -1; -1 as well in the plane itself.
int sideOfPortal(const Portal& portal, const Vec3& x, double reach) {
  const Vec3& origin = portal.vertices[0];
  const Vec3 n = glm::normalize(newellNormal(portal.vertices));
  const double d = glm::dot(n, x - origin);
  if (std::abs(d) <= 1e-6 * reach || std::abs(d) > reach) return -1;
  for (const Vec3& corner : {portal.vertices[1], portal.vertices.back()}) {
    const Vec3 edge = corner - origin;
    const double length = glm::length(edge), along = glm::dot(edge, x - origin) / length;
    if (along < -reach || along > length + reach) return -1;
  }
  return d > 0.0 ? portal.cellB : portal.cellA;
}

// The label of the voxel next to the patch's own along its normal's main axis; kUnreached when it
// is solid (a face in a gap narrower than a voxel, or within a voxel of a wall across it), or when
// a polygon lies between (the back of a cabinet 2 cm from an exterior wall; the end of a wall at an
// angle to the axes, whose voxel ahead is past the wall it runs into). Near a portal of that cell (a floor just past a doorway, whose voxel ahead the cell beyond took:
// cells meet within a voxel or two of the door's plane, and anywhere across a wall at an angle to
// the axes), the cell on the side of the portal the patch faces: that of a point half a voxel in
// front of it, so that the wall around the door goes by the side it faces.
std::int32_t labelAhead(const VoxelGrid& g, const VoxelLabels& labels, const Occluders& occluders,
                        const std::vector<Portal>& portals, const Patch& p) {
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (std::abs(p.normal[a]) > std::abs(p.normal[axis])) axis = a;
  // The patch's own voxel, on the front side when it lies on a voxel boundary (both are solid).
  Index3 v = g.voxelOf(p.centroid + p.normal * (1e-6 * g.voxel));
  v[axis] += p.normal[axis] > 0 ? 1 : -1;
  if (!g.inside(v)) return kOutsideCell;
  const std::int32_t l = labels.label[g.index(v)];
  for (const Portal& portal : portals)
    if (portal.cellA == l || portal.cellB == l)
      if (const int side = sideOfPortal(portal, p.centroid + p.normal * (0.5 * g.voxel), 2.0 * g.voxel); side >= 0)
        return side;
  if (l >= kOutsideCell && occluders.segmentBlocked(p.centroid, g.corner(v) + 0.5 * g.voxel, p.polygon, p.polygon))
    return kUnreached;
  return l >= kOutsideCell ? l : kUnreached;
}

// The nearest cell voxel in front of the patch within `reach` voxels, else the nearest one behind
// it (a face towards a wall a few centimetres away: the back of a cabinet), else kOutsideCell.
int nearestCell(const VoxelGrid& g, const VoxelLabels& labels, const Patch& p, int reach) {
  const Vec3 start = p.centroid + p.normal * (0.75 * g.voxel);
  const Index3 c = g.voxelOf(start);
  std::array<int, 2> found{kOutsideCell, kOutsideCell};  // in front, behind
  std::array<double, 2> nearest{kInf, kInf};
  for (int dz = -reach; dz <= reach; ++dz)
    for (int dy = -reach; dy <= reach; ++dy)
      for (int dx = -reach; dx <= reach; ++dx) {
        const Index3 v{c[0] + dx, c[1] + dy, c[2] + dz};
        if (!g.inside(v)) continue;
        const std::int32_t l = labels.label[g.index(v)];
        if (l < 0) continue;
        const Vec3 centre = g.corner(v) + 0.5 * g.voxel;
        const int side = glm::dot(centre - p.centroid, p.normal) > 0.0 ? 0 : 1;
        const double d = glm::length(centre - start);
        if (d < nearest[side]) {
          nearest[side] = d;
          found[side] = l;
        }
      }
  return nearest[0] < kInf ? found[0] : found[1];
}

}  // namespace

std::vector<int> cellsFaced(const VoxelGrid& g, const VoxelLabels& labels, const ScenePolygons& polys,
                            const std::vector<Portal>& portals, const std::vector<Patch>& patches, int reach) {
  std::vector<int> out(patches.size());
  std::vector<std::vector<int>> seen(polys.bounds.size());  // per polygon, its patches with a label
  const Occluders occluders(patches);
  for (size_t i = 0; i < patches.size(); ++i) {
    out[i] = labelAhead(g, labels, occluders, portals, patches[i]);
    if (out[i] != kUnreached) seen[patches[i].polygon].push_back(int(i));
  }
  for (size_t i = 0; i < patches.size(); ++i) {
    if (out[i] != kUnreached) continue;
    const std::vector<int>& same = seen[patches[i].polygon];
    int best = -1;
    for (int j : same)
      if (best < 0 || glm::length(patches[j].centroid - patches[i].centroid) <
                          glm::length(patches[best].centroid - patches[i].centroid))
        best = j;
    out[i] = best >= 0 ? out[best] : nearestCell(g, labels, patches[i], reach);
  }
  return out;
}

}  // namespace radmesh
