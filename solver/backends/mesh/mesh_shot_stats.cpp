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

namespace {
nlohmann::json countsJson(const emu::CostCounts& c) {
  auto cls = [](const emu::ClassCounts& k) {
    return nlohmann::json{{"ops", k.ops},           {"hops", k.hops},         {"byte_hops", k.byteHops},
                          {"messages", k.messages}, {"rounds", k.rounds},     {"byte_rounds", k.byteRounds},
                          {"flops", k.flops},       {"int_ops", k.intOps},    {"host_seconds", k.hostSeconds}};
  };
  return {{"xnet", cls(c.xnet)},     {"router", cls(c.router)}, {"alu", cls(c.alu)},
          {"reduce", cls(c.reduce)}, {"scan", cls(c.scan)},     {"sort", cls(c.sort)},
          {"max_collisions", c.maxCollisions}, {"memory_high_water_bytes", c.memoryHighWaterBytes}};
}
}  // namespace

ShotStats shotStats(const MeshShotStats& m) {
  nlohmann::json phases = nlohmann::json::array();
  for (const MeshPhaseCost& p : m.phases) {
    nlohmann::json counts = countsJson(p.counts);
    // The peaks are the machine's since the iteration began, not the phase's own.
    counts.erase("max_collisions");
    counts.erase("memory_high_water_bytes");
    phases.push_back({{"name", p.name},
                      {"emulated_seconds", p.emulatedSeconds},
                      {"host_seconds", p.hostSeconds},
                      {"op_counts", std::move(counts)}});
  }
  return {"emulated MP-1",
          m.emulatedSeconds,
          {{"depth_a_max", m.depthAMax},
           {"depth_b_max", m.depthBMax},
           {"depth_a_hist", m.depthAHist},
           {"depth_b_hist", m.depthBHist},
           {"emulated_seconds", m.emulatedSeconds},
           {"host_seconds", m.hostSeconds},
           {"passes", m.passes},
           {"op_counts", countsJson(m.counts)},
           {"phases", std::move(phases)}}};
}

std::vector<int> depthHistogram(const std::vector<int>& depths) {
  const int most = depths.empty() ? 0 : *std::max_element(depths.begin(), depths.end());
  std::vector<int> hist(most + 1, 0);
  for (int d : depths) ++hist[d];
  return hist;
}

}  // namespace radmesh
