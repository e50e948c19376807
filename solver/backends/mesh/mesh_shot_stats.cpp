#include "solver/backends/mesh/mesh_shot_stats.h"

#include <algorithm>

namespace radmesh {

PhaseClock::PhaseClock(const emu::MeshMachine& machine, MeshShotStats& stats, std::string name)
    : machine_(machine), stats_(stats), name_(std::move(name)), before_(machine.costs()),
      start_(std::chrono::steady_clock::now()) {}

PhaseClock::~PhaseClock() {
  const emu::CostCounts spent = machine_.costs() - before_;
  const double host = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  auto it = std::find_if(stats_.phases.begin(), stats_.phases.end(),
                         [&](const MeshPhaseCost& p) { return p.name == name_; });
  if (it == stats_.phases.end()) it = stats_.phases.insert(stats_.phases.end(), MeshPhaseCost{name_, {}, 0.0, 0.0});
  it->counts += spent;
  it->emulatedSeconds += emu::emulatedSeconds(spent).total();
  it->hostSeconds += host;
}

std::vector<int> depthHistogram(const std::vector<int>& depths) {
  const int most = depths.empty() ? 0 : *std::max_element(depths.begin(), depths.end());
  std::vector<int> hist(most + 1, 0);
  for (int d : depths) ++hist[d];
  return hist;
}

}  // namespace radmesh
