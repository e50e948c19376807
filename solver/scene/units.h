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

// For a scene scaled by `metresPerUnit` (--units) to a size no building, room or luminaire has,
// under kSmallestModelM or over kLargestModelM across (a building drawn in metres, read with --units
// mm, is millimetres across and solves silently): the warning naming `file`, the size it came to and
// the --units that gives a plausible size nearest a room's (or leaving it out); else empty.
std::string implausibleUnitsWarning(const Scene& scene, double metresPerUnit, const std::string& file);
inline constexpr double kSmallestModelM = 0.05;  // examp1's luminaire is 1.2 m, cube.mgf in cm 0.1 m
inline constexpr double kLargestModelM = 1e5;    // a site plan of a town, not a continent

// For a scene over a kilometre across, read in metres (a building drawn in millimetres looks like
// a town), the line saying so and how to read it in another unit; else empty.
std::string unitsNote(const Scene& scene);

}  // namespace radmesh
