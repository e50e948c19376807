// `radmesh bench accuracy SCENE`: what each projection, resolution and cell size buys in accuracy
// and costs in time, against a reference solution on the same mesh.
#include <fmt/core.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>

#include "cli/bench.h"
#include "cli/plot.h"
#include "cli/stats_json.h"
#include "solver/accuracy.h"
#include "solver/effects_plan.h"
#include "solver/meshing.h"
#include "solver/progressive_solver.h"
#include "solver/scene_loader.h"

namespace radmesh::cli {

namespace {

struct Setting {
  std::string label;  // "plane r3", "plane r5", "hemicube"
  Projection projection;
  double ratio;
};

struct Point {
  Setting setting;
  int resolution = 0;
  double cellM = 0.0;
  size_t patches = 0;
  double msPerIteration = 0.0;
  double secondsTo95 = -1.0, secondsTo99 = -1.0;  // -1: not reached within the cap
  double error95 = -1.0, error99 = -1.0;
  double memoryMiB = 0.0;
};

// Item buffer (patch id and 1/depth) and delta form-factor table: 20 bytes a pixel.
double projectionMiB(Projection p, int n) {
  const double pixels = p == Projection::Hemicube ? 3.0 * n * n : p == Projection::Plane ? double(n) * n : 0.0;
  return pixels * 20.0 / (1024.0 * 1024.0);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

struct Reference {
  std::string how;
  std::vector<Rgb> radiosity;
  double seconds = 0.0;
};

// Convex enclosure: analytic form factors are exact. Otherwise the finest hemicube converged far.
Reference solveReference(const Scene& scene, const std::vector<Patch>& patches, const AccuracyArgs& args) {
  SolveOptions o;
  o.threads = args.threads;
  o.until = args.referenceUntil;
  o.maxIterations = args.maxIterations * 10;
  const bool convex = isConvexEnclosure(scene);
  o.projection = convex ? Projection::Analytic : Projection::Hemicube;
  o.resolution = args.referenceResolution;
  const auto start = std::chrono::steady_clock::now();
  ProgressiveSolver solver(scene, patches, o);
  while (!solver.done()) solver.step();
  Reference ref;
  ref.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ref.radiosity = solver.radiosity();
  ref.how = convex ? fmt::format("analytic form factors to C={}", o.until)
                   : fmt::format("hemicube {}x{} to C={} ({} iterations)", o.resolution, o.resolution, o.until,
                                 solver.history().size());
  return ref;
}

Point measure(const Scene& scene, const std::vector<Patch>& patches, const Setting& setting, int n, double cellM,
              const Reference& ref, const AccuracyArgs& args, std::vector<std::pair<double, double>>* trace) {
  SolveOptions o;
  o.projection = setting.projection;
  o.ratio = setting.ratio;
  o.resolution = n;
  o.until = 0.99;
  o.threads = args.threads;
  o.maxIterations = args.maxIterations;
  ProgressiveSolver solver(scene, patches, o);
  Point p{setting, n, cellM, patches.size()};
  p.memoryMiB = projectionMiB(setting.projection, n);
  std::vector<double> perIteration;
  double elapsed = 0.0;
  while (!solver.done()) {
    const IterationRecord& r = solver.step();
    perIteration.push_back(r.seconds);
    elapsed += r.seconds;
    if (trace) trace->emplace_back(r.convergence, relativeRmsError(patches, solver.radiosity(), ref.radiosity));
    if (p.secondsTo95 < 0 && r.convergence >= 0.95) {
      p.secondsTo95 = elapsed;
      p.error95 = relativeRmsError(patches, solver.radiosity(), ref.radiosity);
    }
  }
  if (solver.convergence() >= 0.99) {
    p.secondsTo99 = elapsed;
    p.error99 = relativeRmsError(patches, solver.radiosity(), ref.radiosity);
  }
  p.msPerIteration = 1e3 * median(perIteration);
  return p;
}

// Points no other point beats in both time and error, in order of time.
std::vector<std::pair<double, double>> paretoFront(std::vector<std::pair<double, double>> points) {
  std::sort(points.begin(), points.end());
  std::vector<std::pair<double, double>> front;
  for (const auto& pt : points)
    if (front.empty() || pt.second < front.back().second) front.push_back(pt);
  return front;
}

void writeCsv(const std::string& path, const std::vector<Point>& points) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot write");
  fmt::print(out, "projection,ratio,resolution,cell_m,patches,ms_per_iteration,seconds_to_95,seconds_to_99,"
                  "error_at_95,error_at_99,memory_mib\n");
  for (const Point& p : points)
    fmt::print(out, "{},{},{},{},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.4g}\n", toString(p.setting.projection),
               p.setting.ratio, p.resolution, p.cellM, p.patches, p.msPerIteration, p.secondsTo95, p.secondsTo99,
               p.error95, p.error99, p.memoryMiB);
}

void drawFigures(const std::string& stem, const std::string& sceneName, const std::vector<Point>& points,
                 const std::vector<std::pair<double, double>>& trace, const std::string& traceLabel) {
  Plot cost{"Error against time to C=0.99: " + sceneName, "seconds to C = 0.99", "relative RMS error of B", true,
            true, {}};
  std::vector<std::pair<double, double>> all;
  for (const Point& p : points) {
    if (p.secondsTo99 <= 0) continue;
    const std::string title = fmt::format("{} cell {}", p.setting.label, p.cellM);
    auto it = std::find_if(cost.series.begin(), cost.series.end(), [&](const Series& s) { return s.title == title; });
    if (it == cost.series.end()) it = cost.series.insert(cost.series.end(), Series{title, {}, "linespoints"});
    it->points.emplace_back(p.secondsTo99, std::max(p.error99, 1e-9));
    all.emplace_back(p.secondsTo99, std::max(p.error99, 1e-9));
  }
  cost.series.push_back({"Pareto front", paretoFront(all), "lines lw 3 lc rgb 'black'"});
  drawPlot(cost, stem + "-error-vs-time.png");

  Plot conv{"Convergence C against true error (" + traceLabel + "): " + sceneName, "convergence C",
            "relative RMS error of B", false, true, {{traceLabel, trace, "lines"}}};
  drawPlot(conv, stem + "-error-vs-convergence.png");
}

}  // namespace

AccuracyArgs quickAccuracyArgs(AccuracyArgs args) {
  args.cells = {args.cells.front()};
  args.resolutions = {32, 64, 128};
  args.referenceResolution = 256;
  args.referenceUntil = 0.995;
  return args;
}

nlohmann::json benchAccuracy(const AccuracyArgs& args) {
  const Scene scene = loadScene(args.scene);
  const std::vector<Setting> settings = {
      {"plane r3", Projection::Plane, 3.0}, {"plane r5", Projection::Plane, 5.0}, {"hemicube", Projection::Hemicube, 3.0}};
  std::vector<Point> points;
  nlohmann::json references = nlohmann::json::array();
  std::vector<std::pair<double, double>> trace;
  std::string traceLabel;
  fmt::print("{:<9} {:>5} {:>7} {:>8} {:>10} {:>9} {:>9} {:>10} {:>10} {:>8}\n", "setting", "N", "cell m", "patches",
             "ms/iter", "s to .95", "s to .99", "err @.95", "err @.99", "MiB");
  for (double cell : args.cells) {
    const std::vector<Patch> patches = meshScene(scene, cell);
    const Reference ref = solveReference(scene, patches, args);
    fmt::print("cell {} m, {} patches: reference {} in {:.2f} s\n", cell, patches.size(), ref.how, ref.seconds);
    references.push_back({{"cell", cell}, {"patches", patches.size()}, {"how", ref.how}, {"seconds", ref.seconds}});
    for (const Setting& setting : settings) {
      for (int n : args.resolutions) {
        // One error-against-convergence trace: the paper's setting at the middle resolution.
        const bool traced = trace.empty() && setting.projection == Projection::Plane && setting.ratio == 3.0 &&
                            n == args.resolutions[args.resolutions.size() / 2];
        if (traced) traceLabel = fmt::format("plane r3 {}x{}, cell {}", n, n, cell);
        const Point p = measure(scene, patches, setting, n, cell, ref, args, traced ? &trace : nullptr);
        fmt::print("{:<9} {:>5} {:>7.3f} {:>8} {:>10.3f} {:>9.3f} {:>9.3f} {:>10.4f} {:>10.4f} {:>8.2f}\n",
                   setting.label, n, cell, p.patches, p.msPerIteration, p.secondsTo95, p.secondsTo99, p.error95,
                   p.error99, p.memoryMiB);
        points.push_back(p);
      }
    }
  }
  nlohmann::json rows = nlohmann::json::array();
  for (const Point& p : points)
    rows.push_back({{"projection", toString(p.setting.projection)}, {"ratio", p.setting.ratio},
                    {"resolution", p.resolution}, {"cell", p.cellM}, {"patches", p.patches},
                    {"ms_per_iteration", p.msPerIteration}, {"seconds_to_95", p.secondsTo95},
                    {"seconds_to_99", p.secondsTo99}, {"error_at_95", p.error95}, {"error_at_99", p.error99},
                    {"memory_mib", p.memoryMiB}});
  nlohmann::json traceJson = nlohmann::json::array();
  for (const auto& [c, e] : trace) traceJson.push_back({{"convergence", c}, {"error", e}});
  nlohmann::json result = {{"scene", scene.source}, {"references", references}, {"points", rows},
                           {"trace_label", traceLabel}, {"trace", traceJson}};
  if (!args.outDir.empty()) {
    std::filesystem::create_directories(args.outDir);
    const std::string stem = (std::filesystem::path(args.outDir) / args.name).string();
    writeCsv(stem + ".csv", points);
    writeJson(stem + ".json", result);
    drawFigures(stem, scene.source, points, trace, traceLabel);
    fmt::print("wrote {0}.csv, {0}.json, {0}-error-vs-time.png, {0}-error-vs-convergence.png\n", stem);
  }
  return result;
}

}  // namespace radmesh::cli
