#pragma once
// glTF 2.0 (.gltf / .glb) import through tinygltf.
#include <tiny_gltf.h>

#include <array>
#include <string>
#include <vector>

#include "solver/scene/scene.h"

namespace radmesh {

// Reads the triangles (lists, strips and fans, indexed or not) of every mesh under the default scene's roots
// (scene 0's when none is named, or every root node's without scenes), in world space through the node transforms (matrix or
// TRS); points and lines, which have no area, are warned about and skipped. Materials: rho = baseColorFactor x the
// baseColorTexture's texel average, E = emissiveFactor x KHR_materials_emissive_strength (W/m^2);
// see gltf_material.h. KHR_lights_punctual lights on the nodes become the scene's lights
// (gltf_lights.h; a `range` is warned about and not applied). Primitives without a material get a grey default (warned about). Coplanar
// adjacent triangles of one material are merged into polygons (coplanar_merge.h). Throws
// SceneError naming the file and the element (JSON, GLB container, buffer, accessor, node, mesh
// primitive, material) on bad input; the scene is not validated here (loadScene does that).
Scene importGltf(const std::string& path, std::vector<std::string>* warnings = nullptr);

// What a bake made by another tool holds: the triangles importGltf reads (unmerged), with their
// vertices' COLOR_0 when every triangle primitive has one.
struct GltfColouredTriangles {
  std::vector<Polygon> triangles;           // world space, counter-clockwise from the front
  std::vector<std::array<Rgb, 3>> colours;  // per triangle; empty when a triangle primitive lacks COLOR_0
  bool emits = false;                       // some material emits light
};
GltfColouredTriangles readGltfColouredTriangles(const tinygltf::Model& model, const std::string& path);

}  // namespace radmesh
