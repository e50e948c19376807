#pragma once
// Environment projection (the paper's section 1.5, projection phase): a patch is moved into the
// shooter's frame, clipped against the near plane of a projection face and mapped onto that
// face's pixels. Shared by the native and mesh back ends so both see identical polygons.
#include <array>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "solver/meshing/patch.h"

namespace radmesh {

// One planar projection surface at depth 1 above the shooter: the single plane, or one face of the
// hemicube. Face coordinates (a, b, depth) are signed axes of the shooter's frame (u, v, n).
struct ProjectionFace {
  std::array<int, 3> axis{0, 1, 2};         // local axis (0 u, 1 v, 2 n) giving a, b, depth
  std::array<double, 3> sign{1.0, 1.0, 1.0};
  double a0 = -1.0, a1 = 1.0;               // window on the face, at depth 1
  double b0 = -1.0, b1 = 1.0;
  int width = 0;                            // pixels along a
  int height = 0;                           // pixels along b
  // A parallel projection along depth (a directional light's beam): the window is in metres of
  // the frame, and the item buffer's "inverse depth" holds the negated depth, which like 1/depth
  // grows toward the viewer and is affine over a plane.
  bool parallel = false;

  double pixelWidth() const { return (a1 - a0) / width; }
  double pixelHeight() const { return (b1 - b0) / height; }
  // Face coordinates (a, b) at depth 1 of the centre of pixel (column, row).
  glm::dvec2 pixelCentre(int column, int row) const;
  // The shooter-frame direction of the face point (a, b) at depth 1.
  Vec3 toLocal(glm::dvec2 faceAB) const;
};

// A patch in a shooter's frame: origin at the shooter's centroid, axes (u, v, n).
struct LocalPolygon {
  std::array<Vec3, 4> vertices;  // set by whoever makes one, all four (not cleared first: a hot path)
  int vertexCount = 0;
  Vec3 normal{0.0};          // the patch's unit normal in the shooter's frame
  double planeOffset = 0.0;  // normal . x for every point x of the patch; < 0: the shooter sees its front
  Vec3 centroid{0.0};

  bool seenFromFront() const { return planeOffset < 0.0; }
  std::span<const Vec3> corners() const { return {vertices.data(), static_cast<size_t>(vertexCount)}; }
};

LocalPolygon toShooterFrame(const Patch& shooter, const Patch& patch);
Vec3 toShooterFrame(const Patch& shooter, const Vec3& point);
Vec3 directionInShooterFrame(const Patch& shooter, const Vec3& direction);
// The patch in the shooter's frame, or nothing when it lies wholly behind the shooter, where no
// projection face sees it: the first step of the projection phase in both back ends.
std::optional<LocalPolygon> inShooterView(const Patch& shooter, const Patch& patch);

// The part of a patch in front of a face's near plane, in the face's pixel coordinates (pixel
// (i, j) spans [i, i+1] x [j, j+1], its centre at (i + 0.5, j + 0.5)).
struct ScreenPolygon {
  static constexpr int kMaxVertices = 5;  // a quad clipped by one plane
  std::array<glm::dvec2, kMaxVertices> vertices;  // the first vertexCount are set
  int vertexCount = 0;
  // 1/depth is affine in pixel coordinates under a perspective projection: true perspective
  // depth anywhere on the patch, from its plane (robust for slivers, unlike vertex interpolation).
  double inverseDepthX = 0.0, inverseDepthY = 0.0, inverseDepthC = 0.0;
  bool parallel = false;  // a light's parallel beam (its depth ties: scan_conversion.h)
};

// Clips against depth > nearDepth and projects. False when nothing is left in front, or nothing
// within two pixels of the face's window.
// nearDepth is a length relative to the scene's scale; a patch edge-on to the shooter
// (|planeOffset| <= nearDepth) projects to a line and is refused too.
bool projectOntoFace(const LocalPolygon& patch, const ProjectionFace& face, double nearDepth,
                     ScreenPolygon& out);

// Face coordinates (a, b, depth) of a point in the shooter's frame.
Vec3 toFace(const ProjectionFace& face, const Vec3& local);

// The inverse depth, along the ray through face point (a, b) at depth 1, of the plane of `patch`.
double inverseDepthAlong(const LocalPolygon& patch, const ProjectionFace& face, glm::dvec2 faceAB);

// The near plane for a scene: a length far below its features, far above rounding at its
// coordinates (1e-9 of its bounding box's diagonal).
double sceneNearDepth(const std::vector<Patch>& patches);

}  // namespace radmesh
