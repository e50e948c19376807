#include "cli/stats_json.h"

#include <stdexcept>

#include "cli/output_file.h"

namespace radmesh::cli {

namespace {

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
          {"cache_hits", r.cacheHits},
          {"elements_split", r.elementsSplit}};
  if (r.shotStats) j.update(r.shotStats->figures);  // the back end's own figures, whichever it is
  return j;
}

}  // namespace

nlohmann::json ledgerJson(const Ledger& l) {
  nlohmann::json j = {{"emitted", l.emitted},       {"absorbed", l.absorbed},
                      {"absorbed_by_back_faces", l.absorbedByBackFaces}, {"unshot", l.unshot},
                      {"not_captured", l.notCaptured}, {"escaped", l.escaped}, {"light_outside", l.lightOutside},
                      {"light_on_back_faces", l.lightOnBackFaces}, {"imbalance", l.imbalance()}};
  if (l.portalIn > 0.0 || l.portalOut > 0.0) j.update({{"portal_in", l.portalIn}, {"portal_out", l.portalOut}});
  return j;
}

nlohmann::json optionsJson(const SolveOptions& o) {
  nlohmann::json j = {{"backend", toString(o.backend)}, {"projection", toString(o.projection)},
          {"resolution", o.resolution},     {"ratio", o.ratio},                       {"shooters", o.shooters},
          {"threads", o.threads},           {"until", o.until},                       {"until_unshot", o.untilUnshot},
          {"subdivide", toString(o.subdivide)}, {"min_element", o.minElementM},
          {"element_rows", toString(resolvedElementRows(o))},
          {"split_contrast", o.splitContrast}, {"split_shadows", o.splitShadows},
          {"split_regather", o.splitRegatherAll ? "all" : "last"},
          {"cache_mb", o.formFactorCacheBytes / 1048576.0}};
  // The plane's mapping onto PEs and the machine are the mesh back end's alone.
  if (o.backend == Backend::Mesh)
    j.update({{"mapping", toString(o.mapping)}, {"pe_grid", peGridText(o.machine)}, {"pe_memory_kb", o.machine.memoryKb}});
  return j;
}

nlohmann::json solveStats(const ProgressiveSolver& solver, const std::string& scene, double seconds, size_t resumedAt) {
  const SolveOptions& o = solver.options();
  const ProjectionSummary capture = solver.projectionSummary();
  nlohmann::json perIteration = nlohmann::json::array();
  for (const IterationRecord& r : solver.history()) perIteration.push_back(iterationJson(r));
  nlohmann::json j = optionsJson(o);
  j.update({{"scene", scene},
          {"patches", solver.patches().size()},
          {"elements", solver.elements().size()},
          {"captured_fraction", capture.capturedFraction},
          {"delta_form_factor_sum", capture.deltaFormFactorSum},
          {"iterations", solver.history().size()},
          {"convergence", solver.convergence()},
          {"unshot_fraction", solver.ledger().unshotFraction()},
          {"seconds", seconds},
          {"resumed_after_iterations", resumedAt},
          {"per_iteration", std::move(perIteration)},
          {"ledger", ledgerJson(solver.ledger())},
          {"effects", effectsJson(solver.effectsPlan())}});
  return j;
}

nlohmann::json effectsJson(const EffectsPlan& plan) {
  nlohmann::json effects = nlohmann::json::object();
  for (const Effect& e : plan.effects) effects[e.name] = {{"on", e.on}, {"reason", e.reason}};
  return effects;
}

void writeJson(const std::string& path, const nlohmann::json& document) {
  std::ofstream out = openOutput(path);
  out << document.dump() << '\n';  // compact: a per-iteration document runs to megabytes indented
  out.close();  // what is still buffered can fail too
  if (!out) throw std::runtime_error(path + ": write failed (disk full?)");
}

}  // namespace radmesh::cli
