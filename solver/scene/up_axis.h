#pragma once
// Which axis of a scene points up: what cameras, walking and the bake (glTF is y-up) follow.
#include <string>

#include "solver/scene/scene.h"

namespace radmesh {

// `--up`: the format's own convention (not given), an axis, or a guess from the geometry.
enum class UpChoice { Format, X, Y, Z, Auto };

// "x", "y", "z" or "auto"; throws OptionError naming --up otherwise.
UpChoice parseUpChoice(const std::string& text);
const char* upAxisName(int axis);  // "x", "y", "z"

// A right-handed frame (across, along, up) for each up axis: z up (x, y, z), y up (x, -z, y), x up
// (y, z, x). Walking starts from the corner at the least `across` and `along`, and a bake turns its
// scene onto glTF's y up by taking one frame onto the other, so both keep the same start view.
struct UpFrame {
  Vec3 across, along, up;
};
UpFrame upFrame(int axis);

// p in the frame of `upAxis` taken onto y-up's: a rotation (no mirror), the identity for y.
Vec3 rotateToYUp(const Vec3& p, int upAxis);

// --up auto (docs/scene-formats.md, "Up axis"): floors face up at the bottom, ceiling lights face
// down. Per axis, the score is the share of the bounds' cross-section covered by faces facing along
// the axis (cosine at least 0.95) within its lowest tenth, when they make at least 5 % of the
// total area, plus the share of the emitting area facing against it. Up is the best-scoring axis;
// ties go to z, then y.
int guessUpAxis(const Scene& scene);

// Sets scene.upAxis for `choice` (Format keeps the reader's); returns the line to print for Auto,
// which says what was chosen, else empty.
std::string applyUpChoice(Scene& scene, UpChoice choice);

}  // namespace radmesh
