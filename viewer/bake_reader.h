#pragma once
// Reading back a bake written by `radmesh solve --out FILE.glb` (solver/bake/gltf_export.h): its mesh
// and, from COLOR_0 and the radiosityPerColorUnit it records, its vertex radiosity.
#include <optional>
#include <string>
#include <vector>

#include "solver/bake/display_radiosity.h"
#include "viewer/scene_frame.h"

namespace radmesh {

struct Bake {
  DisplayMesh mesh;              // each triangle is its own patch: a bake keeps no patches
  std::vector<Rgb> vertexB;      // W/m^2; what was saturated in COLOR_0 (the lights) stays clipped
  double radiosityPerColorUnit = 1.0;
};

// Empty when the file is a glTF scene rather than a bake (no COLOR_0 or no radiosityPerColorUnit
// in its mesh's extras); throws SceneError for a file that cannot be read.
std::optional<Bake> readBakeGlb(const std::string& path);

// The bake's frame: the saturated (brightest) triangles play the lights that tell the up axis.
SceneFrame bakeFrame(const Bake& bake);

}  // namespace radmesh
