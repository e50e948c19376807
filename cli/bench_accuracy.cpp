// `radmesh bench accuracy SCENE`: what each projection, resolution and cell size buys in accuracy
// and costs in time, against a reference solution on the same mesh.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <filesystem>
#include <map>

#include "cli/bench.h"
#include "cli/bench_accuracy_figures.h"
#include "cli/bench_timing.h"
#include "cli/csv.h"
#include "solver/io/output_path.h"
#include "cli/image_error.h"
#include "solver/radiosity/accuracy.h"
#include "solver/radiosity/effects_plan.h"
#include "solver/meshing/meshing.h"
#include "solver/radiosity/progressive_solver.h"
#include "solver/scene/scene_error.h"
#include "cli/scene_input.h"

namespace radmesh::cli {

using namespace accuracy_sweep;

namespace {

std::string label(const Setting& s) { return settingLabel(toString(s.projection), s.ratio); }

std::string label(const Subdivision& s) {
  if (s.subdivide == Subdivide::Off) return "off";
  return s.rows == ElementRows::Auto ? fmt::format("{} {}", toString(s.subdivide), s.minElementM)
                                     : fmt::format("{} {} {}", toString(s.subdivide), s.minElementM, toString(s.rows));
}

// Item buffer (patch id and 1/depth) and delta form-factor table: 20 bytes a pixel.
double projectionMiB(Projection p, int n) {
  const double pixels = p == Projection::Hemicube ? 3.0 * n * n : p == Projection::Plane ? double(n) * n : 0.0;
  return pixels * 20.0 / (1024.0 * 1024.0);
}

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
  // Its time is not compared, and without adaptive splits a cached row is bitwise the row projected again.
  o.formFactorCacheBytes = defaultFormFactorCacheBytes();
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
        "unshot: the errors against it could not be trusted (raise --max-iterations or --reference-until-unshot)",
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

SolveOptions measuredOptions(const Setting& setting, int n, const Subdivision& subdivision, const AccuracyArgs& args) {
  SolveOptions o;
  o.projection = setting.projection;
  o.ratio = setting.ratio;
  o.resolution = n;
  o.until = 1.0;  // measure() decides where to stop
  o.threads = 1;  // timed on one core, by its CPU time (below)
  o.maxIterations = args.maxIterations;
  o.subdivide = subdivision.subdivide;
  o.minElementM = subdivision.minElementM;
  o.elementRows = subdivision.rows;
  o.splitContrast = args.splitContrast;
  o.formFactorCacheBytes = formFactorCacheBytes(Backend::Native, args.cacheMb);
  return o;
}

// Solves to C = 0.99 and, when asked, on to --until-unshot; a trace goes as far as the reference.
Point measure(const Scene& scene, const std::vector<Patch>& patches, const Setting& setting, int n, double cellM,
              const Subdivision& subdivision, const Reference& ref, const AccuracyArgs& args,
              ImageErrorProbe& pictures, std::vector<TracePoint>* trace) {
  ProgressiveSolver solver(scene, patches, measuredOptions(setting, n, subdivision, args));
  Point p{setting, n, cellM, patches.size(), subdivision};
  p.memoryMiB = projectionMiB(setting.projection, n);
  std::vector<double> perIteration;
  size_t iterationsTo99 = 0;
  double elapsed = 0.0;
  auto measured = [&] {
    return trace ? asFarAsTheReference(solver, args) : p.secondsTo99 >= 0 && (args.untilUnshot <= 0 || p.secondsToUnshot >= 0);
  };
  // Pictures of what a user would see: the receivers, elements where there are any.
  auto pictureError = [&] { return pictures.error(solver.elements(), solver.displayElementRadiosity()); };
  while (!solver.done() && !measured()) {
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
      p.imageError95 = pictureError();
    }
    if (p.secondsTo99 < 0 && r.convergence >= 0.99) {
      p.secondsTo99 = elapsed;
      p.error99 = relativeRmsError(scene, patches, solver.radiosity(), ref.radiosity);
      p.imageError99 = pictureError();
      iterationsTo99 = perIteration.size();
    }
    if (args.untilUnshot > 0 && p.secondsToUnshot < 0 && r.ledger.unshotFraction() <= args.untilUnshot) {
      p.secondsToUnshot = elapsed;
      p.errorAtUnshot = relativeRmsError(scene, patches, solver.radiosity(), ref.radiosity);
      p.imageErrorAtUnshot = pictureError();
    }
  }
  p.elements = solver.elements().size();
  // The cost per iteration of the range every point covers, not of the trace's long tail.
  if (iterationsTo99 > 0) perIteration.resize(iterationsTo99);
  p.msPerIteration = 1e3 * median(perIteration);
  return p;
}

// A figure, or a dash where it was not measured (not reached within the cap, or no viewer to draw).
std::string shown(double value, int decimals) { return value < 0.0 ? "-" : fmt::format("{:.{}f}", value, decimals); }

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

namespace {

std::vector<Setting> chosenSettings(const AccuracyArgs& args) {
  std::vector<Setting> settings;
  for (const std::string& name : args.projections) {
    // The bench's own list: the solve's message would offer analytic, which it does not sweep.
    const Projection p = name == "plane" ? Projection::Plane : name == "hemicube" ? Projection::Hemicube : Projection::Analytic;
    if (p == Projection::Plane) {
      settings.push_back({p, 3.0});
      settings.push_back({p, 5.0});
    } else if (p == Projection::Hemicube) {
      settings.push_back({p, 3.0});
    } else {
      throw OptionError("bench accuracy --projections '" + name + "': give plane (ratios 3 and 5) or hemicube");
    }
  }
  if (settings.empty()) throw OptionError("bench accuracy needs at least one --projections value: plane or hemicube");
  return settings;
}

// The receivers a cell is measured with: off on every cell, uniform and adaptive on the subdivided cells.
std::vector<Subdivision> subdivisionsOf(double cell, const std::vector<double>& subdividedCells,
                                        const AccuracyArgs& args) {
  std::vector<Subdivision> out;
  const bool subdivided = std::ranges::find(subdividedCells, cell) != subdividedCells.end();
  for (const std::string& name : args.subdivide) {
    const Subdivide mode = parseSubdivide(name);
    if (mode == Subdivide::Off) out.push_back({mode, 0.0});
    if (mode == Subdivide::Off || !subdivided) continue;
    const bool ownList = mode == Subdivide::Adaptive && !args.adaptiveMinElements.empty();
    for (const std::string& rows : args.elementRows)
      for (double m : ownList ? args.adaptiveMinElements : args.minElements) {
        SolveOptions o;  // adaptive with 0: a quarter of the cell, as solve takes it
        o.subdivide = mode;
        o.minElementM = m;
        defaultMinElement(o, cell);
        const Subdivision s{mode, o.minElementM, parseElementRows(rows)};
        if (std::ranges::find(out, s) == out.end()) out.push_back(s);  // 0 and a quarter of the cell: one
      }
  }
  return out;
}

// Every option checked before the references take their minutes.
std::vector<double> checkedSubdividedCells(const AccuracyArgs& args, const std::vector<Setting>& settings) {
  if (args.subdivide.empty()) throw OptionError("bench accuracy needs at least one --subdivide value: off, uniform or adaptive");
  if (!(args.untilUnshot >= 0.0 && args.untilUnshot < 1.0))
    throw OptionError("bench accuracy --until-unshot must be a fraction in [0, 1), e.g. 0.01 (0: C = 0.99 only)");
  for (double cell : args.cells)  // one message naming the list's own flag, before any is compared
    if (!(cell > 0.0 && std::isfinite(cell)))
      throw OptionError(fmt::format("bench accuracy --cell-sizes {}: give cell sizes in metres greater than 0, e.g. "
                                    "--cell-sizes 0.5,0.381", cell));
  std::vector<double> subdivided = args.subdivideCells;
  if (subdivided.empty()) subdivided.push_back(*std::ranges::max_element(args.cells));
  for (double cell : subdivided)
    if (std::ranges::find(args.cells, cell) == args.cells.end())
      throw OptionError(fmt::format("bench accuracy --subdivide-cells {}: not one of --cell-sizes; give sizes from that list",
                                    cell));
  for (const Subdivision& s : subdivisionsOf(subdivided.front(), subdivided, args))
    validateOptions(measuredOptions(settings.front(), args.resolutions.front(), s, args));
  return subdivided;
}

}  // namespace

nlohmann::json benchAccuracy(const AccuracyArgs& given) {
  AccuracyArgs args = given;
  const Scene scene = loadCommandScene(args.scene, /*strict=*/false, args.daylight, args.up, args.metresPerUnit);
  if (!args.cellsGiven)
    for (double& cell : args.cells) cell *= chooseCell(scene).cellM / kDefaultCellM;
  if (args.cells.empty() || args.resolutions.empty())
    throw OptionError("bench accuracy needs at least one --cell-sizes value and one --resolutions value");
  checkResolution(args.referenceResolution, "--reference-resolution");
  for (int n : args.resolutions) checkResolution(n, "--resolutions");
  // A reference coarser than what it judges scores its own error as theirs (an analytic one has none).
  if (const int finestN = *std::ranges::max_element(args.resolutions);
      args.referenceResolution < finestN && !isConvexEnclosure(scene))
    throw OptionError(fmt::format("bench accuracy --reference-resolution {} is coarser than --resolutions' {}: give "
                                  "a reference at least as fine, e.g. {}",
                                  args.referenceResolution, finestN, 2 * finestN));
  if (!(args.referenceUnshot > 0.0 && args.referenceUnshot < 1.0))
    throw OptionError("--reference-until-unshot must be a fraction in (0, 1), e.g. 0.001");
  if (!(args.referenceUntil > 0.0 && args.referenceUntil <= 1.0))
    throw OptionError(fmt::format("--reference-until must be a convergence in (0, 1], e.g. 0.999; got {}", args.referenceUntil));
  if (!args.outDir.empty()) makeOutputFolder("--out-dir", args.outDir);
  const double finest = *std::ranges::min_element(args.cells);
  if (!(args.referenceCellM == 0.0 || (args.referenceCellM > 0.0 && args.referenceCellM < finest)))
    throw OptionError(fmt::format(
        "bench accuracy --reference-cell {}: give a cell finer than the finest of --cell-sizes ({} m), e.g. {}, or 0 "
        "for the finest of --cell-sizes itself",
        args.referenceCellM, finest, finest / 2));
  const std::vector<Setting> settings = chosenSettings(args);
  const std::vector<double> subdividedCells = checkedSubdividedCells(args, settings);
  std::vector<double> cells = args.cells;
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  std::map<double, std::vector<Patch>> meshes;
  std::map<double, Reference> refs;
  // The pictures' reference is solved first: a patch mesh, whatever the sweep's receivers, so that
  // it is the same for every method. Without --reference-cell it is the finest swept mesh's own.
  ImageErrorProbe pictures(scene);
  const double pictureCell = args.referenceCellM > 0.0 ? args.referenceCellM : cells.front();
  nlohmann::json pictureReference;
  if (args.referenceCellM > 0.0) {
    const std::vector<Patch> patches = meshScene(scene, pictureCell);
    const Reference ref = solveReference(scene, patches, args);
    pictures.setReference(patches, ref.displayRadiosity);
    fmt::print("cell {} m, {} patches, not swept: the pictures' reference {} in {:.2f} s\n", pictureCell,
               patches.size(), ref.how, ref.seconds);
    pictureReference = {{"cell", pictureCell}, {"patches", patches.size()}, {"how", ref.how}, {"seconds", ref.seconds}};
  }
  nlohmann::json references = nlohmann::json::array();
  for (double cell : cells) {
    const std::vector<Patch>& patches = meshes[cell] = meshScene(scene, cell);
    const Reference& ref = refs[cell] = solveReference(scene, patches, args);
    if (cell == pictureCell) pictures.setReference(patches, ref.displayRadiosity);
    const double imageError = pictures.error(patches, ref.displayRadiosity);
    fmt::print("cell {} m, {} patches: reference {} in {:.2f} s; its pictures differ from the reference pictures "
               "(cell {} m) by {:.2f} levels RMS\n",
               cell, patches.size(), ref.how, ref.seconds, pictureCell, imageError);
    references.push_back({{"cell", cell},
                          {"patches", patches.size()},
                          {"how", ref.how},
                          {"seconds", ref.seconds},
                          {"image_rmse", imageError}});
    if (cell == pictureCell) pictureReference = references.back();
  }
  std::vector<Point> points;
  std::vector<Trace> traces;
  fmt::print("the sweep: one thread, its CPU time, {}\n", benchCacheText(args.cacheMb));
  fmt::print("{:<9} {:>5} {:>7} {:>8} {:>10} {:>9} {:>9} {:>10} {:>10} {:>8} {:>8} {:<15} {:>8} {:>9} {:>10}\n",
             "setting", "N", "cell m", "patches", "ms/iter", "s to .95", "s to .99", "err @.95", "err @.99",
             "img @.99", "MiB", "subdivide", "elements", "s unshot", "img unshot");
  // Coarse to fine, as a user would try them.
  for (auto cell = cells.rbegin(); cell != cells.rend(); ++cell) {
    const std::vector<Patch>& patches = meshes[*cell];
    for (const Setting& setting : settings) {
      for (int n : args.resolutions) {
        for (const Subdivision& subdivision : subdivisionsOf(*cell, subdividedCells, args)) {
          // Error-against-convergence traces on the coarsest mesh at the middle resolution, patches
          // only: the paper's plane, and the hemicube.
          const bool traced = cell == cells.rbegin() && n == args.resolutions[args.resolutions.size() / 2] &&
                              !(setting.projection == Projection::Plane && setting.ratio == 5.0) &&
                              subdivision.subdivide == Subdivide::Off;
          if (traced) traces.push_back({setting, n, *cell, {}});
          const Point p = measure(scene, patches, setting, n, *cell, subdivision, refs[*cell], args, pictures,
                                  traced ? &traces.back().points : nullptr);
          fmt::print("{:<9} {:>5} {:>7.3f} {:>8} {:>10.3f} {:>9} {:>9} {:>10} {:>10} {:>8} {:>8.2f} {:<15} {:>8} {:>9} "
                     "{:>10}\n",
                     label(setting), n, *cell, p.patches, p.msPerIteration, shown(p.secondsTo95, 3),
                     shown(p.secondsTo99, 3), shown(p.error95, 4), shown(p.error99, 4), shown(p.imageError99, 2),
                     p.memoryMiB, label(subdivision), p.elements, shown(p.secondsToUnshot, 3),
                     shown(p.imageErrorAtUnshot, 2));
          points.push_back(p);
        }
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
                    {"memory_mib", p.memoryMiB}, {"subdivide", toString(p.subdivision.subdivide)},
                    {"min_element", p.subdivision.minElementM}, {"elements", p.elements},
                    {"seconds_to_unshot", p.secondsToUnshot}, {"error_at_unshot", p.errorAtUnshot},
                    {"image_rmse_at_unshot", p.imageErrorAtUnshot}, {"element_rows", toString(p.subdivision.rows)}});
  nlohmann::json tracesJson = nlohmann::json::array();
  for (const Trace& trace : traces) {
    nlohmann::json points = nlohmann::json::array();
    for (const TracePoint& t : trace.points)
      points.push_back({{"iteration", t.iteration},
                        {"seconds", t.seconds},
                        {"convergence", t.convergence},
                        {"error", t.error},
                        {"unshot_fraction", t.unshotFraction}});
    tracesJson.push_back({{"label", traceLabel(label(trace.setting), trace.resolution, trace.cellM)}, {"points", points}});
  }
  nlohmann::json result = {{"scene", scene.source}, {"references", references},
                           {"picture_reference", pictureReference}, {"points", rows},
                           {"traces", tracesJson},
                           {"image_cameras", pictures.cameraCount()}, {"until_unshot", args.untilUnshot},
                           {"split_contrast", args.splitContrast}, {"cache_mb", args.cacheMb}};
  if (!args.outDir.empty()) {
    const std::string stem = (std::filesystem::path(args.outDir) / args.name).string();
    writeCsv(stem + ".csv", pointsTable(points, pictureCell));
    writeCsv(stem + "-traces.csv", tracesTable(traces));
    const std::vector<std::string> drawn = drawAccuracyFigures(stem, args.name, stem);  // none without gnuplot
    fmt::print("wrote {0}.csv, {0}-traces.csv{1}\n", stem, drawn.empty() ? "" : fmt::format(" and the plots {}-*.png", stem));
  }
  return result;
}

}  // namespace radmesh::cli
