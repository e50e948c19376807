// `radmesh plot ...`: the tables and figures of docs/ drawn from the CSV committed beside them.
// `plot paper --stats DIR` first gathers the stats JSON of docs/reproduce-paper.sh's solves into that CSV.
#include <fmt/core.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/bench.h"
#include "cli/bench_ranks.h"
#include "cli/commands.h"
#include "cli/csv.h"
#include "solver/io/output_path.h"
#include "solver/scene/scene_error.h"
#include "cli/plot.h"

namespace radmesh::cli {

namespace {

using Points = std::vector<std::pair<double, double>>;

const std::vector<std::string> kMappings = {"hierarchical", "cut-and-stack", "adaptive"};
const std::vector<int> kResolutions = {64, 128, 256};

// Varshney & Prins' section 1.6, drawn beside this scene's figures.
const Points kPaperSeconds = {{64, 0.24}, {128, 0.45}, {256, 2.15}};  // Table 1.1, MP-1 s per iteration
const std::map<std::string, Points> kPaperDepth = {{"a", {{64, 10.6}, {128, 6.5}, {256, 4.4}}},  // Table 1.2
                                                   {"b", {{64, 20.4}, {128, 11.3}, {256, 10.6}}}};
const Points kPaperReuse = {{53.03, 2}, {76.57, 3},  {88.76, 3},  {94.40, 3},  // Table 1.3: C %, rows reused
                            {97.20, 6}, {98.61, 39}, {99.30, 216}};

struct PaperArgs {
  std::string name;
  std::string statsDir;  // empty: draw from the CSV as it is
  std::string csv;
  std::string imagesDir;
};

// One row per iteration of the ten solves; run is the mapping, or "reuse" for Table 1.3's native solve.
CsvTable gatherStats(const PaperArgs& args) {
  CsvTable t{.columns = {"run", "resolution", "iteration", "convergence", "seconds", "emulated_seconds", "depth_a_max",
              "depth_b_max", "reused_rows_total"}};
  // `backend`, `mapping` and `resolution` (0: any): what the file's name says its solve was.
  auto add = [&](const std::string& run, const std::string& file, const std::string& backend,
                 const std::string& mapping, int resolution) {
    const std::string path = fmt::format("{}/paper-{}-{}.json", args.statsDir, args.name, file);
    std::ifstream in(path);
    if (!in) throw OptionError(path + ": cannot read (docs/reproduce-paper.sh writes it)");
    try {
      const nlohmann::json stats = nlohmann::json::parse(in);
      const std::string n = std::to_string(stats.at("resolution").get<int>());
      const std::string wasBackend = stats.at("backend"), wasMapping = stats.value("mapping", "");
      if (wasBackend != backend || (backend == "mesh" && wasMapping != mapping) ||
          (resolution > 0 && n != std::to_string(resolution)))
        throw OptionError(fmt::format(
            "{}: the stats of a {} solve{} at {}, where its name says {}{}{} (fix: write it again with "
            "docs/reproduce-paper.sh)",
            path, wasBackend, wasBackend == "mesh" ? ", mapping " + wasMapping + "," : "", n, backend,
            backend == "mesh" ? ", mapping " + mapping : "", resolution > 0 ? " at " + std::to_string(resolution) : ""));
      for (const nlohmann::json& i : stats.at("per_iteration")) {
        // The native solve has no emulated machine: its fields stay empty.
        auto mesh = [&](const char* key) { return i.contains(key) ? fmt::format("{:.6g}", i[key].get<double>()) : ""; };
        t.rows.push_back({run, n, std::to_string(i.at("iteration").get<int>()),
                          fmt::format("{:.9g}", i.at("convergence").get<double>()),
                          fmt::format("{:.4g}", i.at("seconds").get<double>()), mesh("emulated_seconds"),
                          mesh("depth_a_max"), mesh("depth_b_max"),
                          std::to_string(i.at("reused_rows_total").get<long>())});
      }
    } catch (const nlohmann::json::exception& e) {
      throw OptionError(path + ": not the stats of `radmesh solve --stats`: " + e.what());
    }
  };
  for (const std::string& m : kMappings)
    for (int n : kResolutions) add(m, fmt::format("{}-{}", m, n), "mesh", m, n);
  add("reuse", "reuse", "native", "", 0);
  return t;
}

// The rows of one run in order; resolution 0: any.
std::vector<size_t> rowsOf(const CsvTable& t, const std::string& run, int resolution = 0) {
  std::vector<size_t> rows;
  for (size_t row = 0; row < t.rows.size(); ++row)
    if (t.text(row, "run") == run && (resolution == 0 || t.number(row, "resolution") == resolution))
      rows.push_back(row);
  if (rows.empty()) throw OptionError(fmt::format("{}: no rows of run {} at {}", t.path, run, resolution));
  return rows;
}

// Up to and including the first iteration at C >= 0.95, where the paper's tables stop.
std::vector<size_t> to95(const CsvTable& t, std::vector<size_t> rows) {
  const auto reached = std::find_if(rows.begin(), rows.end(), [&](size_t r) { return t.number(r, "convergence") >= 0.95; });
  if (reached != rows.end()) rows.erase(reached + 1, rows.end());
  return rows;
}

double meanTo95(const CsvTable& t, const std::string& run, int n, const std::string& column) {
  const std::vector<size_t> rows = to95(t, rowsOf(t, run, n));
  double sum = 0.0;
  for (size_t r : rows) sum += t.number(r, column);
  return sum / double(rows.size());
}

// Two columns of the rows as points; convergence C is drawn in percent.
Points curve(const CsvTable& t, const std::vector<size_t>& rows, const std::string& x, const std::string& y) {
  auto drawn = [&](size_t r, const std::string& column) { return (column == "convergence" ? 100.0 : 1.0) * t.number(r, column); };
  Points points;
  for (size_t r : rows) points.emplace_back(drawn(r, x), drawn(r, y));
  return points;
}

void printTables(const CsvTable& t, const std::string& name) {
  fmt::print("Table 1.1 / 1.2 ({}, 4096 PEs, to C = 0.95), every mapping; s/iteration are averages\n", name);
  fmt::print("| mapping | resolution | iterations | emulated MP-1 s/iteration | host s/iteration | avg max depth (a) | "
             "avg max depth (b) |\n|---|---|---|---|---|---|---|\n");
  std::vector<std::string> short95;  // runs that stopped before C = 0.95
  for (const std::string& m : kMappings)
    for (int n : kResolutions) {
      const std::vector<size_t> rows = to95(t, rowsOf(t, m, n));
      const double reached = t.number(rows.back(), "convergence");
      if (reached < 0.95) short95.push_back(fmt::format("{} at {}x{} stopped at C = {:.3f}", m, n, n, reached));
      fmt::print("| {} | {}x{} | {}{} | {:.3f} | {:.4f} | {:.1f} | {:.1f} |\n", m, n, n, rows.size(),
                 reached < 0.95 ? "+" : "", meanTo95(t, m, n, "emulated_seconds"), meanTo95(t, m, n, "seconds"),
                 meanTo95(t, m, n, "depth_a_max"), meanTo95(t, m, n, "depth_b_max"));
    }
  for (const std::string& run : short95)
    fmt::print(stderr, "radmesh: warning: {}: its row (+) averages every iteration it ran, not those to C = 0.95 "
               "(solve it again to --until 0.95)\n", run);
  fmt::print("\nTable 1.3: form-factor rows reused (shooters shot before), cumulative\n"
             "| iteration | rows reused so far | convergence % |\n|---|---|---|\n");
  const std::vector<size_t> reuse = rowsOf(t, "reuse");
  const std::vector<int> marks = {13, 32, 59, 101, 177, 392, 1105, 2462};  // the paper's rows
  for (size_t r : reuse)
    if (std::count(marks.begin(), marks.end(), int(t.number(r, "iteration"))) || r == reuse.back())
      fmt::print("| {} | {} | {:.2f} |\n", t.text(r, "iteration"), t.text(r, "reused_rows_total"),
                 100.0 * t.number(r, "convergence"));
}

void drawFigures(const CsvTable& t, const PaperArgs& args) {
  const std::string& name = args.name;
  const std::string png = fmt::format("{}/paper-{}-", args.imagesDir, name);
  Plot convergence{.title = fmt::format("Figure 1.3: convergence by single-plane resolution ({}, mesh backend)", name),
                   .xLabel = "iteration", .yLabel = "convergence C %"};
  for (int n : kResolutions)
    convergence.series.push_back(
        {fmt::format("{}x{}", n, n), curve(t, rowsOf(t, "hierarchical", n), "iteration", "convergence"), "lines"});
  drawPlot(convergence, png + "convergence.png");
  // Points show where there are few enough iterations to tell apart.
  size_t longest = 0;
  for (int n : kResolutions) longest = std::max(longest, rowsOf(t, "hierarchical", n).size());
  const std::string style = longest <= 100 ? "linespoints" : "lines";
  for (const std::string stage : {"a", "b"}) {
    Plot depth{.title = fmt::format("Figure 1.4: max item-buffer depth at stage ({}) per iteration ({})", stage, name),
               .xLabel = "iteration", .yLabel = "max depth over PEs"};
    for (int n : kResolutions)
      depth.series.push_back(
          {fmt::format("{}x{}", n, n), curve(t, rowsOf(t, "hierarchical", n), "iteration", "depth_" + stage + "_max"), style});
    drawPlot(depth, png + "depth-" + stage + ".png");
  }
  // The paper's Tables 1.1-1.3 beside this scene's, drawn.
  const std::vector<std::string> resolutionAxis = {"set logscale x 2", "set xtics (64, 128, 256)", "set xrange [45:360]"};
  auto means = [&](const std::string& m, const std::string& column) {
    Points points;
    for (int n : kResolutions) points.emplace_back(n, meanTo95(t, m, n, column));
    return points;
  };
  Plot seconds{.title = fmt::format("Table 1.1: MP-1 seconds per iteration to C = 0.95 ({})", name),
               .xLabel = "single-plane resolution", .yLabel = "MP-1 seconds per iteration (log)", .logX = true,
               .logY = true, .series = {{"paper (Sitterson 365 office, measured)", kPaperSeconds}},
               .settings = resolutionAxis};
  for (const std::string& m : kMappings) seconds.series.push_back({"radmesh " + m + " (emulated)", means(m, "emulated_seconds")});
  drawPlot(seconds, png + "table11.png");
  Plot depths{.title = fmt::format("Table 1.2: average max item-buffer depth to C = 0.95 ({})", name),
              .xLabel = "single-plane resolution", .yLabel = "average of the max depth over PEs (log)", .logX = true,
              .logY = true, .settings = resolutionAxis};
  for (const auto& [stage, points] : kPaperDepth) depths.series.push_back({"paper (" + stage + ")", points});
  for (const std::string& m : kMappings)
    for (const std::string stage : {"a", "b"})
      depths.series.push_back({"radmesh " + m + " (" + stage + ")", means(m, "depth_" + stage + "_max")});
  drawPlot(depths, png + "table12.png");
  const std::vector<size_t> reuse = rowsOf(t, "reuse");
  Plot reused{.title = fmt::format("Table 1.3: form-factor rows reused against convergence ({})", name),
              .xLabel = "convergence C %", .yLabel = "rows reused so far",
              .series = {{"paper", kPaperReuse},
                         {fmt::format("radmesh (native, {0}x{0})", t.text(reuse.front(), "resolution")),
                          curve(t, reuse, "convergence", "reused_rows_total"), "lines"}},
              .settings = {"set xrange [50:100]"}};
  drawPlot(reused, png + "table13.png");
  fmt::print("\ndrew {0}convergence.png, -depth-a.png, -depth-b.png, -table11.png, -table12.png, -table13.png\n", png);
}

}  // namespace

void addPlotCommand(CLI::App& app) {
  CLI::App* plot = app.add_subcommand("plot", "Draw the tables and figures of docs/ from their CSV (gnuplot)");
  plot->require_subcommand(1);
  auto paper = std::make_shared<PaperArgs>();
  CLI::App* cmd = plot->add_subcommand("paper", "Print the tables and draw the figures of docs/paper-reproduction.md");
  cmd->add_option("name", paper->name, "The scene's name in the file names: paper-NAME-*")->required();
  cmd->add_option("--stats", paper->statsDir,
                  "First gather the stats docs/reproduce-paper.sh wrote here (paper-NAME-*.json) into --csv");
  cmd->add_option("--csv", paper->csv, "The solves' figures, a row per iteration")->required();
  cmd->add_option("--images", paper->imagesDir, "Folder of the PNGs")->required();
  cmd->callback([paper] {
    requireGnuplot();
    // The inputs first: one missing leaves no folder or file behind.
    if (!paper->statsDir.empty()) {  // --csv is written, not read: never over a stats file
      const CsvTable gathered = gatherStats(*paper);
      checkOutputPath("--csv", paper->csv, ".csv", "the gathered figures are CSV");
      writeCsv(paper->csv, gathered), fmt::print("wrote {}\n", paper->csv);
    }
    const CsvTable table = readCsv(paper->csv);
    makeOutputFolder("--images", paper->imagesDir);  // before any table
    printTables(table, paper->name);
    drawFigures(table, *paper);
  });
  auto stem = std::make_shared<std::string>();
  CLI::App* accuracy =
      plot->add_subcommand("accuracy", "Draw the figures of docs/accuracy.md from STEM.csv and STEM-traces.csv");
  accuracy->add_option("stem", *stem, "DIR/NAME of `radmesh bench accuracy --out-dir DIR --name NAME` (or DIR/NAME.csv)")
      ->required();
  auto outDir = std::make_shared<std::string>();
  accuracy->add_option("--out-dir", *outDir,
                       "Folder of the PNGs (default: beside the CSV, where a doc's committed figures are replaced)");
  accuracy->callback([stem, outDir] {
    requireGnuplot();
    // The table's own path is what a user has at hand: its stem is meant.
    const std::filesystem::path given(*stem);
    const std::string s = given.extension() == ".csv" ? (given.parent_path() / given.stem()).string() : *stem;
    const std::string name = std::filesystem::path(s).filename().string();
    const std::string pngStem = outDir->empty() ? s : (std::filesystem::path(*outDir) / name).string();
    for (const std::string& png : drawAccuracyFigures(s, name, pngStem)) fmt::print("drew {}\n", png);
  });
  auto model = std::make_shared<std::string>();
  auto scaling = std::make_shared<std::vector<std::string>>();
  CLI::App* scalingCmd = plot->add_subcommand(
      "scaling", "Draw docs/scaling.md's figures from `bench solve --distributed --csv STEM` on 1, 2, 4 ranks");
  scalingCmd->add_option("model", *model, "The model's CSV (STEM-model.csv)")->required();
  scalingCmd->add_option("ranks", *scaling, "The runs' per-rank CSVs (STEM-ranks.csv), a 1-rank run among them")
      ->required();
  auto png = std::make_shared<std::string>();
  scalingCmd->add_option("--png", *png, "Stem of the PNGs: STEM-speedup.png, STEM-bytes.png")->required();
  scalingCmd->callback([model, scaling, png] {
    requireGnuplot();
    readCsv(*model);  // the inputs first: one missing leaves no folder
    for (const std::string& csv : *scaling) readCsv(csv);
    checkOutputPath("--png", *png, "", "");  // STEM-speedup.png and STEM-bytes.png go beside it
    drawScalingFigures(*model, *scaling, *png);
  });
}

}  // namespace radmesh::cli
