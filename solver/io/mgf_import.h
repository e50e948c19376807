#pragma once
// MGF 2.0 (Materials and Geometry Format, G. Ward) import.
#include <string>

#include "solver/scene/scene.h"

namespace radmesh {

// Reads an MGF file and its includes; throws SceneError naming the file, line and entity on bad input.
// Warnings (ignored specular/transmission terms, desaturated colours, bent faces split into
// triangles) go to `warnings` if given. Conventions: docs/scene-formats.md.
Scene importMgf(const std::string& path, std::vector<std::string>* warnings = nullptr);

}  // namespace radmesh
