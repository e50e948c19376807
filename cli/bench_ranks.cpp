#include "cli/bench_ranks.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

#include "cli/plot.h"

namespace radmesh::cli {

namespace {

// Up to 256 processes: the development machine's 1, 2 and 4, then a cluster's.
const std::vector<int> kModelRanks = {1, 2, 4, 8, 16, 32, 64, 128, 256};

std::string number(double v) { return fmt::format("{:.6g}", v); }

}  // namespace

// The cells cut as the solver cuts them for `ranks`; every round waits for its busiest process
// (bulk synchronous), then two all-gathers and the neighbour messages.
ModelPoint modelPoint(const RunShape& shape, int ranks, const ClusterModel& cluster) {
  const std::vector<int> owner = assignCellsToRanks(shape.cellLoads, ranks);
  ModelPoint p{.ranks = ranks};
  std::vector<double> work(ranks, 0.0);
  for (const std::vector<int>& shots : shape.shotsPerRound) {
    std::vector<double> round(ranks, 0.0);
    for (size_t c = 0; c < shots.size(); ++c) round[owner[c]] += static_cast<double>(shots[c]) * shape.cellPatches[c];
    p.roundMaxWork += *std::max_element(round.begin(), round.end());
    for (int r = 0; r < ranks; ++r) work[r] += round[r];
  }
  p.maxWork = *std::max_element(work.begin(), work.end());
  for (double w : work) p.meanWork += w / ranks;
  // Each round's message from one process to another: its links' runs, or the full bins if shorter.
  std::vector<std::set<int>> neighbours(ranks);
  std::vector<double> bytes(ranks, 0.0);
  for (size_t round = 0; round < static_cast<size_t>(shape.rounds); ++round) {
    std::map<std::pair<int, int>, std::pair<size_t, size_t>> message;  // (from, to): run doubles, links
    for (const PortalLinkTraffic& link : shape.links) {
      const int from = owner[link.cell], to = owner[link.twinCell];
      if (from == to) continue;
      neighbours[from].insert(to);
      message[{from, to}].first += static_cast<size_t>(link.runDoubles.at(round));
      ++message[{from, to}].second;
    }
    for (const auto& [pair, size] : message)
      bytes[pair.first] += 8.0 * static_cast<double>(portalMessageDoubles(size.first, size.second * shape.bins));
  }
  const double rounds = std::max(shape.rounds, 1);
  double exchange = 0.0;
  for (int r = 0; r < ranks; ++r) {
    p.maxMessages = std::max(p.maxMessages, static_cast<int>(neighbours[r].size()));
    p.maxBytesPerRound = std::max(p.maxBytesPerRound, bytes[r] / rounds);
    p.allBytesPerRound += bytes[r] / rounds;
    exchange = std::max(exchange, static_cast<double>(neighbours[r].size()) * cluster.latencySeconds +
                                      bytes[r] / rounds / cluster.bytesPerSecond);
  }
  // An all-gather: log2 R latencies, and each process receives everyone else's part.
  const double gather = ranks == 1 ? 0.0
                                   : cluster.latencySeconds * std::ceil(std::log2(ranks)) +
                                         shape.figureBytes * (ranks - 1) / ranks / cluster.bytesPerSecond;
  p.seconds = cluster.secondsPerPatchShot * p.roundMaxWork + shape.rounds * (2.0 * gather + exchange);
  return p;
}

CsvTable ranksCsvTable() {
  return {.columns = {"projection", "resolution", "shooters", "ranks", "rank", "cells", "patches", "shots", "work",
                      "messages", "bytes", "messages_per_round", "bytes_per_round", "gathers", "gather_bytes_per_round",
                      "wall_seconds", "mpi_wait_seconds"}};
}

CsvTable modelCsvTable() {
  return {.columns = {"projection", "resolution", "shooters", "ranks", "max_work", "mean_work", "round_max_work",
                      "max_messages_per_round", "max_bytes_per_round", "all_bytes_per_round", "work_speedup",
                      "round_speedup", "seconds", "speedup"}};
}

nlohmann::json reportRanks(const std::vector<RankFigures>& ranks, const RunShape& shape,
                           const std::vector<std::string>& setting, CsvTable& ranksCsv, CsvTable& modelCsv) {
  const double rounds = std::max(shape.rounds, 1);
  const int n = static_cast<int>(ranks.size());
  fmt::print("  per rank ({} ranks, {} rounds; work in 10^6 patch shots; bytes sent a round, all-gathers apart):\n", n,
             shape.rounds);
  fmt::print("  {:>5} {:>6} {:>8} {:>8} {:>8} {:>10} {:>12} {:>14} {:>10} {:>10}\n", "rank", "cells", "patches", "shots",
             "work", "msgs/round", "bytes/round", "gather B/round", "wall s", "MPI wait s");
  nlohmann::json perRank = nlohmann::json::array();
  double computeSeconds = 0.0, work = 0.0;
  for (int r = 0; r < n; ++r) {
    const RankFigures& f = ranks[r];
    const CellTraffic& t = f.sent;
    fmt::print("  {:>5} {:>6} {:>8} {:>8} {:>8.3f} {:>10.2f} {:>12.0f} {:>14.0f} {:>10.3f} {:>10.3f}\n", r, f.cells,
               f.patches, f.shots, 1e-6 * f.work, t.messages / rounds, t.bytes / rounds, t.gatherBytes / rounds,
               f.wallSeconds, t.waitSeconds);
    perRank.push_back({{"rank", r}, {"cells", f.cells}, {"patches", f.patches}, {"shots", f.shots}, {"work", f.work},
                       {"messages", t.messages}, {"bytes", t.bytes}, {"messages_per_round", t.messages / rounds},
                       {"bytes_per_round", t.bytes / rounds}, {"gathers", t.gathers},
                       {"gather_bytes_per_round", t.gatherBytes / rounds}, {"wall_seconds", f.wallSeconds},
                       {"mpi_wait_seconds", t.waitSeconds}});
    std::vector<std::string> row = setting;
    for (double v : {double(n), double(r), double(f.cells), double(f.patches), double(f.shots), f.work,
                     double(t.messages), double(t.bytes), t.messages / rounds, t.bytes / rounds, double(t.gathers),
                     t.gatherBytes / rounds, f.wallSeconds, t.waitSeconds})
      row.push_back(number(v));
    ranksCsv.rows.push_back(row);
    computeSeconds += f.wallSeconds - t.waitSeconds;
    work += f.work;
  }
  ClusterModel cluster;
  cluster.secondsPerPatchShot = work > 0.0 ? computeSeconds / work : 0.0;
  fmt::print("  model (docs/scaling.md): the cells cut as the solver cuts them, {:.3f} us a patch shot (this run's "
             "wall time out of MPI over its work), {:g} us a message, {:g} GB/s\n",
             1e6 * cluster.secondsPerPatchShot, 1e6 * cluster.latencySeconds, 1e-9 * cluster.bytesPerSecond);
  fmt::print("  {:>5} {:>10} {:>10} {:>12} {:>10} {:>14} {:>14} {:>10} {:>9}\n", "ranks", "max work", "work spd",
             "round spd", "msgs/round", "max B/round", "all B/round", "model s", "speed-up");
  nlohmann::json model = nlohmann::json::array();
  const ModelPoint one = modelPoint(shape, 1, cluster);
  for (int r : kModelRanks) {
    const ModelPoint p = modelPoint(shape, r, cluster);
    const double workSpeedup = p.maxWork > 0 ? one.maxWork / p.maxWork : 0.0;
    const double roundSpeedup = p.roundMaxWork > 0 ? one.roundMaxWork / p.roundMaxWork : 0.0;
    const double speedup = p.seconds > 0 ? one.seconds / p.seconds : 0.0;
    fmt::print("  {:>5} {:>10.3f} {:>10.2f} {:>12.2f} {:>10} {:>14.0f} {:>14.0f} {:>10.3f} {:>9.2f}\n", r,
               1e-6 * p.maxWork, workSpeedup, roundSpeedup, p.maxMessages, p.maxBytesPerRound, p.allBytesPerRound,
               p.seconds, speedup);
    model.push_back({{"ranks", r}, {"max_work", p.maxWork}, {"mean_work", p.meanWork},
                     {"round_max_work", p.roundMaxWork}, {"max_messages_per_round", p.maxMessages},
                     {"max_bytes_per_round", p.maxBytesPerRound}, {"all_bytes_per_round", p.allBytesPerRound},
                     {"work_speedup", workSpeedup}, {"round_speedup", roundSpeedup}, {"seconds", p.seconds},
                     {"speedup", speedup}});
    std::vector<std::string> row = setting;
    for (double v : {double(r), p.maxWork, p.meanWork, p.roundMaxWork, double(p.maxMessages), p.maxBytesPerRound,
                     p.allBytesPerRound, workSpeedup, roundSpeedup, p.seconds, speedup})
      row.push_back(number(v));
    modelCsv.rows.push_back(row);
  }
  return {{"ranks", n}, {"rounds", shape.rounds}, {"seconds_per_patch_shot", cluster.secondsPerPatchShot},
          {"per_rank", std::move(perRank)}, {"model", std::move(model)}};
}

void drawScalingFigures(const std::string& modelCsv, const std::vector<std::string>& ranksCsvs,
                        const std::string& pngStem) {
  const CsvTable model = readCsv(modelCsv);
  using Points = std::vector<std::pair<double, double>>;
  Points ideal, speedup, workSpeedup, roundSpeedup, maxBytes, allBytes;
  for (size_t row = 0; row < model.rows.size(); ++row) {
    const double r = model.number(row, "ranks");
    ideal.emplace_back(r, r);
    speedup.emplace_back(r, model.number(row, "speedup"));
    workSpeedup.emplace_back(r, model.number(row, "work_speedup"));
    roundSpeedup.emplace_back(r, model.number(row, "round_speedup"));
    if (r > 1) maxBytes.emplace_back(r, model.number(row, "max_bytes_per_round"));
    if (r > 1) allBytes.emplace_back(r, model.number(row, "all_bytes_per_round"));
  }
  // Per measured run: the busiest rank's work and wall time, the bytes of the busiest and of all.
  struct Run {
    double maxWork = 0, work = 0, maxWall = 0, maxBytes = 0, allBytes = 0;
  };
  std::map<int, Run> runs;
  std::map<int, std::vector<int>> ranksOfRun;  // each run's rank rows: 0 to N - 1, once each
  // Every run of one setting (projection, resolution, shooters), the model's.
  auto setting = [](const CsvTable& t, size_t row) {
    return t.text(row, "projection") + "," + t.text(row, "resolution") + "," + t.text(row, "shooters");
  };
  const std::string modelled = model.rows.empty() ? "" : setting(model, 0);
  for (const std::string& path : ranksCsvs) {
    const CsvTable t = readCsv(path);
    for (size_t row = 0; row < t.rows.size(); ++row) {
      if (setting(t, row) != modelled)
        throw std::runtime_error(fmt::format("{}, line {}: a run of {}, where the model ({}) is of {}: give runs of "
                                             "one setting",
                                             path, t.lineOfRow[row], setting(t, row), modelCsv, modelled));
      const int ranks = static_cast<int>(t.number(row, "ranks"));
      ranksOfRun[ranks].push_back(static_cast<int>(t.number(row, "rank")));
      Run& run = runs[ranks];
      run.maxWork = std::max(run.maxWork, t.number(row, "work"));
      run.work += t.number(row, "work");
      run.maxWall = std::max(run.maxWall, t.number(row, "wall_seconds"));
      run.maxBytes = std::max(run.maxBytes, t.number(row, "bytes_per_round"));
      run.allBytes += t.number(row, "bytes_per_round");
    }
  }
  for (auto& [ranks, seen] : ranksOfRun) {
    std::sort(seen.begin(), seen.end());
    std::vector<int> whole(static_cast<size_t>(ranks));
    std::iota(whole.begin(), whole.end(), 0);
    if (seen != whole)
      throw std::runtime_error(fmt::format("the {}-rank run has rows for {} rank(s) where it needs one for each of "
                                           "0 to {}: give each run's whole -ranks.csv, once",
                                           ranks, seen.size(), ranks - 1));
  }
  if (!runs.count(1)) throw std::runtime_error("the measured runs hold no 1-rank run: the speed-ups are against it");
  Points measuredWork, measuredWall, measuredMax, measuredAll;
  for (const auto& [r, run] : runs) {
    measuredWork.emplace_back(r, run.work / run.maxWork);
    measuredWall.emplace_back(r, runs[1].maxWall / run.maxWall);
    if (r > 1) measuredMax.emplace_back(r, run.maxBytes), measuredAll.emplace_back(r, run.allBytes);
  }
  const std::vector<std::string> ranksAxis = {"set logscale x 2", "set xrange [0.8:320]"};
  Plot speed{.title = "Cells over MPI ranks: speed-up, the model against the measured runs",
             .xLabel = "ranks", .yLabel = "speed-up over 1 rank", .logX = true, .logY = true,
             .series = {{"ideal", ideal, "lines"},
                        {"model: a cluster (2 us, 1 GB/s), rounds wait for the busiest rank", speedup},
                        {"model: the busiest rank's work, per round", roundSpeedup},
                        {"model: the busiest rank's work, whole solve", workSpeedup},
                        {"measured: the busiest rank's work", measuredWork, "points pointsize 2"},
                        {"measured: wall time, 2 shared cores", measuredWall, "points pointsize 2"}},
             .settings = ranksAxis};
  drawPlot(speed, pngStem + "-speedup.png");
  Plot bytes{.title = "Cells over MPI ranks: portal bytes sent a round, the model against the measured runs",
             .xLabel = "ranks", .yLabel = "bytes a round", .logX = true, .logY = true,
             .series = {{"model: the busiest rank", maxBytes}, {"model: all ranks", allBytes},
                        {"measured: the busiest rank", measuredMax, "points pointsize 2"},
                        {"measured: all ranks", measuredAll, "points pointsize 2"}},
             .settings = ranksAxis};
  drawPlot(bytes, pngStem + "-bytes.png");
  fmt::print("drew {0}-speedup.png, {0}-bytes.png\n", pngStem);
}

}  // namespace radmesh::cli
