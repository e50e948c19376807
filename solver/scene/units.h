#pragma once
// The unit a scene's coordinates are in (`--units`): radmesh works in metres, as glTF defines and
// MGF assumes, but CAD exports in millimetres, centimetres, inches or feet are common.
#include <string>

#include "solver/scene/scene.h"

namespace radmesh {

// Metres per unit for "m", "cm", "mm", "in" or "ft"; throws OptionError naming --units otherwise.
double parseUnits(const std::string& text);

// Scales every coordinate (polygons, point and spot lights) by metresPerUnit. Emittance stays per
// square metre, as MGF's `ed` and glTF's emissive strength are, so an emitter's power follows its
// area in metres: the same as wrapping an MGF file in `xf -s metresPerUnit`.
void scaleScene(Scene& scene, double metresPerUnit);

// For a scene over a kilometre across, read in metres (a building drawn in millimetres looks like
// a town), the line saying so and how to read it in another unit; else empty.
std::string unitsNote(const Scene& scene);

}  // namespace radmesh
