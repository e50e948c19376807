#pragma once
// MGF's curved and solid primitives as planar polygons, in the coordinates the vertices were given
// in (the interpreter transforms them afterwards, like faces). Vertices lie on the true surface,
// so the tessellated area is slightly below the analytic area (-0.64% for a cylinder at 16
// segments). Every polygon is planar and counter-clockwise seen from outside (inside for negative
// radii or a negative prism length, as MGF defines).
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

inline constexpr int kMgfSegmentsAround = 16;  // around every circle
inline constexpr int kMgfSegmentsAcross = 8;   // pole to pole on a sphere, around a torus tube

using MgfPolygons = std::vector<std::vector<Vec3>>;

// sph: 16 x 8 latitude-longitude cells (triangles at the poles, planar trapezoids elsewhere).
MgfPolygons tessellateSphere(const Vec3& centre, double radius);
// cone (and cyl, with equal radii): 16 trapezoids, open ends; a zero radius makes triangles.
MgfPolygons tessellateCone(const Vec3& end1, double radius1, const Vec3& end2, double radius2);
// ring: one 16-gon for a disc (rMin = 0), otherwise 16 trapezoids; facing `normal`.
MgfPolygons tessellateRing(const Vec3& centre, const Vec3& normal, double rMin, double rMax);
// torus: 16 x 8 trapezoids; rMin and rMax are the inner and outer radii, the axis is `normal`.
MgfPolygons tessellateTorus(const Vec3& centre, const Vec3& normal, double rMin, double rMax);
// prism: the base, its copy moved `length` against the base's right-hand normal, and the sides.
MgfPolygons tessellatePrism(const std::vector<Vec3>& base, double length);

}  // namespace radmesh
