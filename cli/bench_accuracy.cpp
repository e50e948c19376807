// `radmesh bench accuracy SCENE`: what each projection, resolution and cell size buys in accuracy
// and costs in time, against a reference solution on the same mesh.
#include <fmt/core.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>

#include "cli/bench.h"
#include "cli/bench_timing.h"
#include "cli/image_error.h"
#include "cli/plot.h"
#include "cli/stats_json.h"
#include "solver/radiosity/accuracy.h"
#include "solver/radiosity/effects_plan.h"
#include "solver/meshing/meshing.h"
#include "solver/radiosity/progressive_solver.h"
#include "solver/scene/scene_error.h"
#include "solver/io/scene_loader.h"

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
  double imageError95 = -1.0, imageError99 = -1.0;  // 8-bit RMSE against the finest mesh's pictures
  double memoryMiB = 0.0;
};

// Item buffer (patch id and 1/depth) and delta form-factor table: 20 bytes a pixel.
double projectionMiB(Projection p, int n) {
  const double pixels = p == Projection::Hemicube ? 3.0 * n * n : p == Projection::Plane ? double(n) * n : 0.0;
  return pixels * 20.0 / (1024.0 * 1024.0);
}

// One iteration of the traced solve: what C says beside the true error and the power still unshot.
struct TracePoint {
  int iteration = 0;
  double seconds = 0.0;  // CPU time so far
  double convergence = 0.0;
  double error = 0.0;           // relative RMS error of B - E against the reference
  double unshotFraction = 0.0;  // unshot power over emitted power
};

struct Trace {
  std::string label;
  std::vector<TracePoint> points;
};

struct Reference {
  std::string how;
  std::vector<Rgb> radiosity;
  std::vector<Rgb> displayRadiosity;
  double seconds = 0.0;
};

// Converged as far as the reference: C, which follows the shooter alone, can pass 0.999 with 5 %
// of the power unshot, so the power left must be small too.
bool asFarAsTheReference(const ProgressiveSolver& solver, const AccuracyArgs& args) {
  return solver.convergence() >= args.referenceUntil && solver.ledger().unshotFraction() <= args.referenceUnshot;
}

// Convex enclosure: analytic form factors are exact. Otherwise the finest hemicube converged far.
Reference solveReference(const Scene& scene, const std::vector<Patch>& patches, const AccuracyArgs& args) {
  SolveOptions o;
  o.threads = args.threads;
  o.until = 1.0;  // asFarAsTheReference decides
  o.maxIterations = args.maxIterations * 10;
  const bool convex = isConvexEnclosure(scene);
  o.projection = convex ? Projection::Analytic : Projection::Hemicube;
  o.resolution = args.referenceResolution;
  const auto start = std::chrono::steady_clock::now();
  ProgressiveSolver solver(scene, patches, o);
  while (!solver.done() && !asFarAsTheReference(solver, args)) solver.step();
  if (!asFarAsTheReference(solver, args))
    throw std::runtime_error(fmt::format(
        "the reference stopped at C = {:.5f} with {:.3f} % unshot after {} iterations, short of C = {} and {} % "
        "unshot: the errors against it could not be trusted (raise --max-iterations or --reference-unshot)",
        solver.convergence(), 100.0 * solver.ledger().unshotFraction(), solver.history().size(), args.referenceUntil,
        100.0 * args.referenceUnshot));
  Reference ref;
  ref.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ref.radiosity = solver.radiosity();
  ref.displayRadiosity = solver.displayRadiosity();
  const std::string reached = fmt::format("C = {:.5f}, {:.3f} % unshot, {} iterations", solver.convergence(),
                                          100.0 * solver.ledger().unshotFraction(), solver.history().size());
  ref.how = convex ? "analytic form factors to " + reached
                   : fmt::format("hemicube {}x{} to {}", o.resolution, o.resolution, reached);
  return ref;
}

Point measure(const Scene& scene, const std::vector<Patch>& patches, const Setting& setting, int n, double cellM,
              const Reference& ref, const AccuracyArgs& args, ImageErrorProbe& pictures,
              std::vector<TracePoint>* trace) {
  SolveOptions o;
  o.projection = setting.projection;
  o.ratio = setting.ratio;
  o.resolution = n;
  o.until = trace ? 1.0 : 0.99;  // a trace goes as far as the reference
  o.threads = 1;  // timed on one core, by its CPU time (below)
  o.maxIterations = args.maxIterations;
  ProgressiveSolver solver(scene, patches, o);
  Point p{setting, n, cellM, patches.size()};
  p.memoryMiB = projectionMiB(setting.projection, n);
  std::vector<double> perIteration;
  size_t iterationsTo99 = 0;
  double elapsed = 0.0;
  while (!solver.done() && !(trace && asFarAsTheReference(solver, args))) {
    const double before = threadCpuSeconds();
    const IterationRecord& r = solver.step();
    const double seconds = threadCpuSeconds() - before;
    perIteration.push_back(seconds);
    elapsed += seconds;
    if (trace)
      trace->push_back({r.iteration, elapsed, r.convergence,
                        relativeRmsError(scene, patches, solver.radiosity(), ref.radiosity),
                        r.ledger.unshotFraction()});
    if (p.secondsTo95 < 0 && r.convergence >= 0.95) {
      p.secondsTo95 = elapsed;
      p.error95 = relativeRmsError(scene, patches, solver.radiosity(), ref.radiosity);
      p.imageError95 = pictures.error(patches, solver.displayRadiosity());
    }
    if (p.secondsTo99 < 0 && r.convergence >= 0.99) {
      p.secondsTo99 = elapsed;
      p.error99 = relativeRmsError(scene, patches, solver.radiosity(), ref.radiosity);
      p.imageError99 = pictures.error(patches, solver.displayRadiosity());
      iterationsTo99 = perIteration.size();
    }
  }
  // The cost per iteration of the range every point covers, not of the trace's long tail.
  if (iterationsTo99 > 0) perIteration.resize(iterationsTo99);
  p.msPerIteration = 1e3 * median(perIteration);
  return p;
}

// A figure, or a dash where it was not measured (not reached within the cap, or no viewer to draw).
std::string shown(double value, int decimals) { return value < 0.0 ? "-" : fmt::format("{:.{}f}", value, decimals); }

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
                  "error_at_95,error_at_99,image_rmse_at_95,image_rmse_at_99,memory_mib\n");
  for (const Point& p : points)
    fmt::print(out, "{},{},{},{},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.4g},{:.4g},{:.4g}\n",
               toString(p.setting.projection), p.setting.ratio, p.resolution, p.cellM, p.patches, p.msPerIteration,
               p.secondsTo95, p.secondsTo99, p.error95, p.error99, p.imageError95, p.imageError99, p.memoryMiB);
}

// Error at C = 0.99 against the time to reach it, a series per setting and cell, Pareto front in black.
Plot errorVersusTime(const std::string& title, const std::string& errorLabel, const std::vector<Point>& points,
                     double Point::*error) {
  Plot plot{title, "seconds to C = 0.99", errorLabel, true, true, {}};
  std::vector<std::pair<double, double>> all;
  for (const Point& p : points) {
    if (p.secondsTo99 <= 0 || p.*error < 0) continue;
    const std::string name = fmt::format("{} cell {}", p.setting.label, p.cellM);
    auto it = std::find_if(plot.series.begin(), plot.series.end(), [&](const Series& s) { return s.title == name; });
    if (it == plot.series.end()) it = plot.series.insert(plot.series.end(), Series{name, {}, "linespoints"});
    // Log axes: an exact zero is drawn at the floor.
    it->points.emplace_back(p.secondsTo99, std::max(p.*error, 1e-9));
    all.push_back(it->points.back());
  }
  plot.series.push_back({"Pareto front", paretoFront(all), "lines lw 3 lc rgb 'black'"});
  return plot;
}

void drawFigures(const std::string& stem, const std::string& sceneName, const std::vector<Point>& points,
                 const std::vector<Trace>& traces) {
  drawPlot(errorVersusTime("Error against time to C=0.99, same mesh: " + sceneName, "relative RMS error of B - E",
                           points, &Point::error99),
           stem + "-error-vs-time.png");
  if (ImageErrorProbe::available())
    drawPlot(errorVersusTime("Picture error against time to C=0.99, across meshes: " + sceneName,
                             "RMSE of the pictures, 8-bit levels", points, &Point::imageError99),
             stem + "-image-error-vs-time.png");
  // Each setting's true error and unshot power; 1 - C of the first, which is what C promises.
  Plot conv{"What convergence C says against the true error: " + sceneName, "iteration", "fraction", false, true, {}};
  for (const Trace& trace : traces) {
    Series error{"error of B - E, " + trace.label, {}, "lines lw 2"}, unshot{"unshot / emitted, " + trace.label, {}, "lines"};
    for (const TracePoint& t : trace.points) {
      error.points.emplace_back(t.iteration, std::max(t.error, 1e-9));
      unshot.points.emplace_back(t.iteration, std::max(t.unshotFraction, 1e-9));
    }
    conv.series.push_back(error);
    conv.series.push_back(unshot);
  }
  if (!traces.empty()) {
    Series remaining{"1 - C, " + traces.front().label, {}, "lines dt 2"};
    for (const TracePoint& t : traces.front().points)
      remaining.points.emplace_back(t.iteration, std::max(1.0 - t.convergence, 1e-9));
    conv.series.push_back(remaining);
  }
  drawPlot(conv, stem + "-error-vs-convergence.png");
}

}  // namespace

AccuracyArgs quickAccuracyArgs(AccuracyArgs args) {
  // Two cells, so that the pictures compare across meshes too.
  if (args.cells.size() > 2) args.cells.resize(2);
  args.resolutions = {32, 64, 128};
  args.referenceResolution = 256;
  args.referenceUntil = 0.995;
  args.referenceUnshot = 0.005;
  return args;
}

nlohmann::json benchAccuracy(const AccuracyArgs& args) {
  const Scene scene = loadScene(args.scene);
  const std::vector<Setting> settings = {
      {"plane r3", Projection::Plane, 3.0}, {"plane r5", Projection::Plane, 5.0}, {"hemicube", Projection::Hemicube, 3.0}};
  if (args.cells.empty() || args.resolutions.empty())
    throw OptionError("bench accuracy needs at least one --cells value and one --resolutions value");
  if (!(args.referenceUnshot > 0.0 && args.referenceUnshot < 1.0))
    throw OptionError("--reference-unshot must be a fraction in (0, 1), e.g. 0.001");
  // The finest mesh's reference is solved first: its pictures are the reference across meshes.
  std::vector<double> cells = args.cells;
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  std::map<double, std::vector<Patch>> meshes;
  std::map<double, Reference> refs;
  ImageErrorProbe pictures(scene);
  nlohmann::json references = nlohmann::json::array();
  for (double cell : cells) {
    const std::vector<Patch>& patches = meshes[cell] = meshScene(scene, cell);
    const Reference& ref = refs[cell] = solveReference(scene, patches, args);
    if (cell == cells.front()) pictures.setReference(patches, ref.displayRadiosity);
    const double imageError = pictures.error(patches, ref.displayRadiosity);
    fmt::print("cell {} m, {} patches: reference {} in {:.2f} s; its pictures differ from the finest mesh's by "
               "{:.2f} levels RMS\n",
               cell, patches.size(), ref.how, ref.seconds, imageError);
    references.push_back({{"cell", cell},
                          {"patches", patches.size()},
                          {"how", ref.how},
                          {"seconds", ref.seconds},
                          {"image_rmse", imageError}});
  }
  std::vector<Point> points;
  std::vector<Trace> traces;
  fmt::print("{:<9} {:>5} {:>7} {:>8} {:>10} {:>9} {:>9} {:>10} {:>10} {:>8} {:>8}\n", "setting", "N", "cell m",
             "patches", "ms/iter", "s to .95", "s to .99", "err @.95", "err @.99", "img @.99", "MiB");
  // Coarse to fine, as a user would try them.
  for (auto cell = cells.rbegin(); cell != cells.rend(); ++cell) {
    const std::vector<Patch>& patches = meshes[*cell];
    for (const Setting& setting : settings) {
      for (int n : args.resolutions) {
        // Error-against-convergence traces on the coarsest mesh at the middle resolution: the
        // paper's plane, and the hemicube.
        const bool traced = cell == cells.rbegin() && n == args.resolutions[args.resolutions.size() / 2] &&
                            setting.label != "plane r5";
        if (traced) traces.push_back({fmt::format("{} {}x{}, cell {}", setting.label, n, n, *cell), {}});
        const Point p = measure(scene, patches, setting, n, *cell, refs[*cell], args, pictures,
                                traced ? &traces.back().points : nullptr);
        fmt::print("{:<9} {:>5} {:>7.3f} {:>8} {:>10.3f} {:>9} {:>9} {:>10} {:>10} {:>8} {:>8.2f}\n", setting.label, n,
                   *cell, p.patches, p.msPerIteration, shown(p.secondsTo95, 3), shown(p.secondsTo99, 3),
                   shown(p.error95, 4), shown(p.error99, 4), shown(p.imageError99, 2), p.memoryMiB);
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
                    {"image_rmse_at_95", p.imageError95}, {"image_rmse_at_99", p.imageError99},
                    {"memory_mib", p.memoryMiB}});
  nlohmann::json tracesJson = nlohmann::json::array();
  for (const Trace& trace : traces) {
    nlohmann::json points = nlohmann::json::array();
    for (const TracePoint& t : trace.points)
      points.push_back({{"iteration", t.iteration},
                        {"seconds", t.seconds},
                        {"convergence", t.convergence},
                        {"error", t.error},
                        {"unshot_fraction", t.unshotFraction}});
    tracesJson.push_back({{"label", trace.label}, {"points", points}});
  }
  nlohmann::json result = {{"scene", scene.source}, {"references", references}, {"points", rows},
                           {"traces", tracesJson},
                           {"image_cameras", pictures.cameraCount()}};
  if (!args.outDir.empty()) {
    std::filesystem::create_directories(args.outDir);
    const std::string stem = (std::filesystem::path(args.outDir) / args.name).string();
    writeCsv(stem + ".csv", points);
    writeJson(stem + ".json", result);
    drawFigures(stem, scene.source, points, traces);
    fmt::print("wrote {0}.csv, {0}.json and the plots {0}-*.png\n", stem);
  }
  return result;
}

}  // namespace radmesh::cli
