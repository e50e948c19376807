#pragma once
// Reading a bake back: radmesh's own (`radmesh solve --out FILE.glb`, solver/bake/gltf_export.h)
// and other tools' (radiosity or light maps baked into vertex colours), its mesh and its vertex
// radiosity, to walk, render and describe with no solve.
#include <optional>
#include <string>
#include <vector>

#include "solver/bake/display_radiosity.h"

namespace radmesh {

struct Bake {
  DisplayMesh mesh;              // each triangle is its own patch: a bake keeps no patches
  std::vector<Rgb> vertexB;      // W/m^2; what was saturated in COLOR_0 (the lights) stays clipped
  double radiosityPerColorUnit = 1.0;
  // glTF's y, as radmesh writes bakes since it records "sourceUp" and as glTF defines for other
  // tools' bakes. A radmesh bake written before is in its scene's own axes and does not say which:
  // guessed as --up auto does (solver/scene/up_axis.h).
  int upAxis = 1;
  int sourceUp = -1;        // the scene's up axis before the bake turned it onto y; -1 unknown
  bool fromRadmesh = true;  // false: another tool's (COLOR_0 on every primitive, no emission)
};

// Empty when `path` does not name a .gltf or .glb file, or names a glTF scene rather than a bake.
// A bake is radmesh's when its one mesh has one primitive with COLOR_0 and its extras hold
// "radiosityPerColorUnit"; another tool's when every triangle primitive under the scene carries
// COLOR_0 and no material emits (COLOR_0 is then the radiosity, radiosityPerColorUnit 1; normals
// are the triangles'). Throws SceneError for a file that cannot be read.
std::optional<Bake> readBake(const std::string& path);

// The bake as scene geometry, for its area, bounds, frame and --up auto: its triangles, with its up
// axis; the saturated ones (the lights, mostly) have an emitting material, the others a grey.
Scene bakeScene(const Bake& bake, const std::string& path);

}  // namespace radmesh
