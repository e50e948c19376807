#pragma once
// Directions leaving a patch, in bins (light passing through a portal, docs/cells.md): the bins
// are the pixels of a hemicube of resolution n over the patch (the top face n x n, the four sides
// n x (n+1)/2). Every bin is a pyramid of directions bounded by planes through the patch's centre,
// so the part of a polygon it sees is a polygon, whose form factor is exact; a bin's own form
// factor is that of its pixel. n <= 1 is one bin: every direction, a diffuse patch.
#include <functional>
#include <span>

#include "solver/scene/scene.h"

namespace radmesh {

int directionBinCount(int n);
// The bin of a direction given in the patch's frame (u, v, n), z >= 0.
int directionBin(int n, const Vec3& local);
// The form factor of the bin's directions (the part of a diffuse patch's power leaving in them).
double directionBinFormFactor(int n, int bin);
// Cuts a polygon, in the patch's frame with the patch's centre at the origin, along the bins:
// add(bin, formFactor) for every bin that sees a part of it, in bin order. The form factors add
// up to pointToPolygonFormFactor(polygon) but for rounding.
void splitOverDirectionBins(int n, std::span<const Vec3> polygon, const std::function<void(int, double)>& add);

}  // namespace radmesh
