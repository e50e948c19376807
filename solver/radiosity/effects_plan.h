#pragma once
// Simulate only what the scene calls for: before solving, decide which effects matter and why.
// Each skip is exact (same answer within the solver's tolerance) and saves time.
#include <string>
#include <vector>

#include "solver/meshing/patch.h"
#include "solver/scene/scene.h"
#include "solver/scene/solve_options.h"

namespace radmesh {

struct Effect {
  std::string name;    // "occlusion", "colour", "interreflection", "near field", "escape"
  bool on = true;
  std::string reason;  // why on or off, in a sentence a user can check
};

struct EffectsPlan {
  bool occlusion = true;        // off: a convex enclosure, analytic form factors suffice
  bool colour = true;           // off: every material and emitter grey, one channel does for three
  bool interreflection = true;  // off: every reflectance zero, one shot per emitter
  bool nearField = true;        // off: no receiver closer to a shooter than the shooter's size
  bool escape = true;           // off: the scene is closed, no light can leave it (what hits nothing
                                //   through seams between patches is booked as escaped all the same)
  bool closed = true;           // isClosed, as found whatever the mode (--effects all turns escape on)
  std::vector<Effect> effects;  // the five above with their reasons, in that order
  // Per shooter patch, the receivers in its near field (solver/formfactors/near_field.h), whatever the mode.
  std::vector<std::vector<int>> nearReceivers;
};

// EffectsMode::All (--effects all) turns every effect on, keeping the analysis in the reasons.
// ProgressiveSolver plans and applies this itself; `radmesh info` only prints it.
EffectsPlan planEffects(const Scene& scene, const std::vector<Patch>& patches, EffectsMode mode);

// True when every polygon has the whole scene on or in front of its plane: the polygons bound a
// convex region from inside, so no patch can hide another from any point of the surface.
bool isConvexEnclosure(const Scene& scene);

// True when no light can leave the scene: every polygon edge is covered by edges of other polygons
// or lies on another's face (a watertight surface), or the edges that are not lie inside closed
// surfaces, and no face looks out of them (lightCanLeave, solver/geometry/scene_rays.h). Casts rays:
// where a solver is at hand, its EffectsPlan::closed has the answer.
bool isClosed(const Scene& scene);

// Throws OptionError for --projection analytic on a scene that is not a convex enclosure: its form
// factors see through everything, so the shadows would be lit (a floor under a plate 290 times too
// bright), without a word where no row sums past 1. The commands check what a user asks for; the
// solver itself takes analytic anywhere, as the tests' oracle.
void checkAnalyticSeesNoShadows(const Scene& scene, Projection projection);

}  // namespace radmesh
