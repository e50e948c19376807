#pragma once
// Patches built directly for the solver's tests, independent of the mesher: single patches,
// subdivided parallelograms and closed boxes, with the scenes that own their materials.
#include <cmath>
#include <vector>

#include "solver/meshing/patch.h"
#include "solver/scene/scene.h"

namespace radmesh::test {

// A convex patch from 3 or 4 vertices, counter-clockwise around its normal. The frame's u is the
// world axis least aligned with the normal, projected into the plane.
inline Patch makePatch(const std::vector<Vec3>& vertices, int material = 0, int polygon = 0) {
  Patch p;
  p.vertexCount = static_cast<int>(vertices.size());
  for (int k = 0; k < p.vertexCount; ++k) p.vertices[k] = vertices[k];
  const Vec3 n = newellNormal(vertices);
  p.areaM2 = 0.5 * glm::length(n);
  p.normal = glm::normalize(n);
  // Area centroid: the fan of triangles from vertex 0, weighted by their areas.
  Vec3 weighted(0.0);
  double area = 0.0;
  for (int k = 1; k + 1 < p.vertexCount; ++k) {
    const double a = 0.5 * glm::length(glm::cross(vertices[k] - vertices[0], vertices[k + 1] - vertices[0]));
    weighted += a * (vertices[0] + vertices[k] + vertices[k + 1]) / 3.0;
    area += a;
  }
  p.centroid = weighted / area;
  // Near-ties go to the lower axis: rounding of a normal far from the origin must not turn the frame.
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(p.normal[k]) < std::abs(p.normal[axis]) - 1e-9) axis = k;
  Vec3 world(0.0);
  world[axis] = 1.0;
  p.frame.n = p.normal;
  p.frame.u = glm::normalize(world - glm::dot(world, p.normal) * p.normal);
  p.frame.v = glm::cross(p.frame.n, p.frame.u);
  p.material = material;
  p.polygon = polygon;
  return p;
}

// The parallelogram corner + s edgeU + t edgeV (s, t in [0, 1]) cut into nu x nv quads, normal
// along edgeU x edgeV, appended to `out`.
inline void addGrid(std::vector<Patch>& out, Vec3 corner, Vec3 edgeU, Vec3 edgeV, int nu, int nv,
                    int material = 0, int polygon = 0) {
  auto at = [&](int s, int t) { return corner + edgeU * (double(s) / nu) + edgeV * (double(t) / nv); };
  for (int t = 0; t < nv; ++t)
    for (int s = 0; s < nu; ++s)
      out.push_back(makePatch({at(s, t), at(s + 1, t), at(s + 1, t + 1), at(s, t + 1)}, material, polygon));
}

struct TestScene {
  Scene scene;
  std::vector<Patch> patches;
};

// A scene's polygon for each patch group, so error messages have something to name.
inline void addPolygon(Scene& scene, Vec3 corner, Vec3 edgeU, Vec3 edgeV, int material) {
  scene.polygons.push_back({{corner, corner + edgeU, corner + edgeU + edgeV, corner + edgeV}, material, ""});
}

// The six faces of the box [0, size] (normals inward), each cut into `divisions` per side; face f
// uses material faceMaterial[f] (floor, ceiling, x=0, x=X, y=0, y=Y).
inline TestScene closedBox(Vec3 size, int divisions, std::vector<Material> materials,
                           std::array<int, 6> faceMaterial = {0, 0, 0, 0, 0, 0}, Vec3 offset = Vec3(0.0)) {
  TestScene t;
  t.scene.source = "test box";
  t.scene.materials = std::move(materials);
  const double X = size.x, Y = size.y, Z = size.z;
  const std::array<std::array<Vec3, 3>, 6> faces{{
      {Vec3(0, 0, 0), Vec3(X, 0, 0), Vec3(0, Y, 0)},  // floor, +z
      {Vec3(0, 0, Z), Vec3(0, Y, 0), Vec3(X, 0, 0)},  // ceiling, -z
      {Vec3(0, 0, 0), Vec3(0, Y, 0), Vec3(0, 0, Z)},  // x = 0, +x
      {Vec3(X, 0, 0), Vec3(0, 0, Z), Vec3(0, Y, 0)},  // x = X, -x
      {Vec3(0, 0, 0), Vec3(0, 0, Z), Vec3(X, 0, 0)},  // y = 0, +y
      {Vec3(0, Y, 0), Vec3(X, 0, 0), Vec3(0, 0, Z)},  // y = Y, -y
  }};
  for (int f = 0; f < 6; ++f) {
    addPolygon(t.scene, offset + faces[f][0], faces[f][1], faces[f][2], faceMaterial[f]);
    addGrid(t.patches, offset + faces[f][0], faces[f][1], faces[f][2], divisions, divisions,
            faceMaterial[f], f);
  }
  return t;
}

inline Material grey(double rho, double emittance = 0.0, const char* name = "grey") {
  return {name, Rgb(rho), Rgb(emittance)};
}

}  // namespace radmesh::test
