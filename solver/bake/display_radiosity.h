#pragma once
// Per-vertex radiosity for Gouraud display: patch radiosity averaged (area-weighted) onto shared
// vertices, never across creases, material boundaries or a surface standing on the seam (a wall
// of no thickness between two rooms' floors). One mesh serves the viewer, the
// offscreen render and the glTF bake.
#include <vector>

#include "solver/meshing/patch.h"

namespace radmesh {

// A triangle mesh for display: three corners per triangle, each with its own smoothing group.
struct DisplayMesh {
  std::vector<Vec3> positions;       // per vertex
  std::vector<Vec3> normals;         // per vertex (the patch normal; flat within a smoothing group)
  std::vector<unsigned> indices;     // triangles
  std::vector<int> patchOfTriangle;  // which patch each triangle came from
  // Per vertex, the patches (and area weights) averaged into it: used to turn patch B into vertex B.
  std::vector<std::vector<std::pair<int, double>>> vertexSources;
};

// Without cracks: a corner of one patch that lies inside an edge of another (a T-vertex,
// solver/bake/t_vertices.h) joins that patch's triangles, and its radiosity is interpolated
// along the edge, so that shading is continuous across it.
DisplayMesh buildDisplayMesh(const std::vector<Patch>& patches);

// Vertex radiosity from patch radiosity (same order as patches), by the mesh's vertexSources.
std::vector<Rgb> vertexRadiosity(const DisplayMesh& mesh, const std::vector<Rgb>& patchRadiosity);

}  // namespace radmesh
