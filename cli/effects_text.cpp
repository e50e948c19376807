#include "cli/effects_text.h"

#include <fmt/core.h>

namespace radmesh::cli {

void printEffects(const EffectsPlan& plan) {
  fmt::print("effects\n");
  for (const Effect& e : plan.effects) fmt::print("  {:<16}{:<4} {}\n", e.name, e.on ? "on" : "off", e.reason);
}

}  // namespace radmesh::cli
