#pragma once
// The effects plan as `radmesh info` and `radmesh solve` print it: one line per effect.
#include "solver/radiosity/effects_plan.h"

namespace radmesh::cli {

void printEffects(const EffectsPlan& plan);

}  // namespace radmesh::cli
