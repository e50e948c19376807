#pragma once
// Merging coplanar adjacent triangles of one material into polygons, so that the way an input
// model happens to be triangulated does not turn into sliver patches when meshed (issue 2).
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

struct MergeReport {
  size_t trianglesIn = 0;
  size_t degenerateDropped = 0;  // triangles with repeated (welded) or collinear corners
  size_t polygonsOut = 0;
};

// Triangles (3-vertex polygons) that share an edge with opposite winding, have the same material
// and lie in the same plane (normal within ~1e-4 rad of the region's first triangle, every corner
// within 1e-6 of the scene's size of its plane) are merged into one polygon: its outer boundary in
// order, counter-clockwise like the triangles, with collinear boundary vertices removed. Vertices
// are welded when they coincide to 1e-7 of the scene's size (float precision), so separately
// stored corners join. The scene's size here is its bounding box's diagonal, but at most a thousand
// of its median triangle's longest edges: one stray triangle far away does not weld the model.
//
// Every output polygon is simple (convex or not): a region is grown only while it stays a
// topological disk, so a region with a hole (a ring around a light, say) comes out as several
// polygons instead of one with a hole. A polygon keeps the origin of its first triangle.
// Triangles degenerate after welding (a repeated corner, or an area below 1e-10 of their longest
// edge squared) are dropped and counted. Polygons with other than 3 vertices, or with a non-finite
// coordinate, are passed through unchanged for validateScene to judge.
std::vector<Polygon> mergeCoplanarTriangles(const std::vector<Polygon>& triangles,
                                            MergeReport* report = nullptr);

}  // namespace radmesh
