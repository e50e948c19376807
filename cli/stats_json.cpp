#include "cli/stats_json.h"

#include <fstream>
#include <stdexcept>

namespace radmesh::cli {

namespace {

nlohmann::json ledgerJson(const Ledger& l) {
  return {{"emitted", l.emitted},       {"absorbed", l.absorbed}, {"unshot", l.unshot},
          {"not_captured", l.notCaptured}, {"escaped", l.escaped}, {"imbalance", l.imbalance()}};
}

nlohmann::json countsJson(const emu::CostCounts& c) {
  auto cls = [](const emu::ClassCounts& k) {
    return nlohmann::json{{"ops", k.ops},           {"hops", k.hops},         {"byte_hops", k.byteHops},
                          {"messages", k.messages}, {"rounds", k.rounds},     {"byte_rounds", k.byteRounds},
                          {"flops", k.flops},       {"int_ops", k.intOps}};
  };
  return {{"xnet", cls(c.xnet)},     {"router", cls(c.router)}, {"alu", cls(c.alu)},
          {"reduce", cls(c.reduce)}, {"scan", cls(c.scan)},     {"sort", cls(c.sort)},
          {"max_collisions", c.maxCollisions}, {"memory_high_water_bytes", c.memoryHighWaterBytes}};
}

void addMeshShot(nlohmann::json& j, const MeshShotStats& m) {
  j["depth_a_max"] = m.depthAMax;
  j["depth_b_max"] = m.depthBMax;
  j["depth_a_hist"] = m.depthAHist;
  j["depth_b_hist"] = m.depthBHist;
  j["emulated_seconds"] = m.emulatedSeconds;
  j["passes"] = m.passes;
  j["op_counts"] = countsJson(m.counts);
  nlohmann::json phases = nlohmann::json::array();
  for (const MeshPhaseCost& p : m.phases)
    phases.push_back({{"name", p.name}, {"emulated_seconds", p.emulatedSeconds}, {"host_seconds", p.hostSeconds}});
  j["phases"] = phases;
}

nlohmann::json iterationJson(const IterationRecord& r) {
  nlohmann::json j = {{"iteration", r.iteration},
          {"shooter", r.shooters.empty() ? -1 : r.shooters.front()},
          {"shooters", r.shooters},
          {"shot_power", r.shotPowerW},
          {"convergence", r.convergence},
          {"unshot_fraction", r.ledger.unshotFraction()},
          {"seconds", r.seconds},
          {"captured_fraction", r.capturedFraction},
          {"reused_rows", r.reusedRows},
          {"reused_rows_total", r.reusedRowsTotal},
          {"cache_hits", r.cacheHits}};
  if (r.meshShot) addMeshShot(j, *r.meshShot);
  return j;
}

}  // namespace

nlohmann::json solveStats(const ProgressiveSolver& solver, const std::string& scene, double seconds) {
  const SolveOptions& o = solver.options();
  const ProjectionSummary capture = solver.projectionSummary();
  nlohmann::json perIteration = nlohmann::json::array();
  for (const IterationRecord& r : solver.history()) perIteration.push_back(iterationJson(r));
  return {{"scene", scene},
          {"patches", solver.patches().size()},
          {"backend", toString(o.backend)},
          {"projection", toString(o.projection)},
          {"mapping", toString(o.mapping)},
          {"resolution", o.resolution},
          {"ratio", o.ratio},
          {"shooters", o.shooters},
          {"threads", o.threads},
          {"until", o.until},
          {"until_unshot", o.untilUnshot},
          {"captured_fraction", capture.capturedFraction},
          {"delta_form_factor_sum", capture.deltaFormFactorSum},
          {"iterations", solver.history().size()},
          {"convergence", solver.convergence()},
          {"unshot_fraction", solver.ledger().unshotFraction()},
          {"seconds", seconds},
          {"per_iteration", std::move(perIteration)},
          {"ledger", ledgerJson(solver.ledger())},
          {"effects", effectsJson(solver.effectsPlan())}};
}

nlohmann::json effectsJson(const EffectsPlan& plan) {
  nlohmann::json effects = nlohmann::json::object();
  for (const Effect& e : plan.effects) effects[e.name] = {{"on", e.on}, {"reason", e.reason}};
  return effects;
}

void writeJson(const std::string& path, const nlohmann::json& document) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot open for writing (check the folder exists and is writable)");
  out << document.dump(2) << '\n';
  if (!out) throw std::runtime_error(path + ": write failed (disk full?)");
}

}  // namespace radmesh::cli
