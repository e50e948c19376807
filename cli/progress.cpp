#include "cli/progress.h"

#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include "cli/interrupt.h"

namespace radmesh::cli {

namespace {

constexpr double kLogInterval = 1.0;        // seconds between lines in a log
constexpr double kTerminalInterval = 0.05;  // a live line redrawn at most 20 times a second

std::string duration(double seconds) {
  if (seconds < 59.5) return fmt::format("{:.0f} s", seconds);
  if (seconds < 3570.0) return fmt::format("{:.0f} min", seconds / 60.0);
  return fmt::format("{:.1f} h", seconds / 3600.0);
}

// The time left at two paces: the average since the start, and the recent one. Neither is right
// alone: the unshot power falls ever slower, so the average is too hopeful (building:10x10's cells
// solve said 1.5 min left at first, and 14 min after 13 min, with 11 % still unshot), while the
// form-factor cache makes later shots faster, so the recent pace is too gloomy (the office: 21 s
// left at 3 s, done at 9 s).
// Where they differ by more than half, and print differently, the line gives both.
std::string timeLeft(double average, double recent) {
  const bool a = std::isfinite(average) && average >= 0.0, r = std::isfinite(recent) && recent >= 0.0;
  if (!a && !r) return "";
  const std::string low = duration(std::min(average, recent)), high = duration(std::max(average, recent));
  if (!a || !r || std::max(average, recent) <= 1.5 * std::min(average, recent) || low == high)
    return fmt::format("  ~{} left", duration(r ? recent : average));
  const size_t unit = low.find(' ');  // "6 s" and "15 s": "6-15 s", within a terminal's line
  if (high.substr(high.find(' ')) == low.substr(unit)) return fmt::format("  ~{}-{} left", low.substr(0, unit), high);
  return fmt::format("  ~{} to {} left", low, high);
}

}  // namespace

Progress::Progress(const SolveOptions& stop, std::FILE* out)
    : Progress(stop, out, isatty(fileno(out)) != 0 ? Mode::Terminal : Mode::Log) {}

Progress::Progress(const SolveOptions& stop, std::FILE* out, Mode mode) : stop_(stop), out_(out), mode_(mode) {}

// How far the solve is toward whichever stopping rule it will meet first: C against --until, the
// unshot power on a log scale (it falls roughly geometrically) against --until-unshot, iterations
// against --max-iterations.
double Progress::fractionDone(const IterationRecord& r) const {
  double done = double(r.iteration) / stop_.maxIterations;
  if (stop_.until < 1.0) done = std::max(done, r.convergence / stop_.until);
  const double unshot = r.ledger.unshotFraction();
  if (stop_.untilUnshot > 0.0 && unshot > 0.0 && unshot < 1.0)
    done = std::max(done, std::log(unshot) / std::log(stop_.untilUnshot));
  return std::clamp(done, 0.0, 1.0);
}

void Progress::print(const IterationRecord& r, double elapsed) {
  const double rate = elapsed > 0.0 ? (r.iteration - startIteration_) / elapsed : 0.0;
  const double done = fractionDone(r);
  const double doneNow = done - startDone_;  // this run's part
  const double unshot = 100.0 * r.ledger.unshotFraction();
  // The recent pace: over the latter half of the time so far.
  if (paces_.empty()) paces_.emplace_back(0.0, startDone_);
  while (paces_.size() > 1 && paces_[1].first <= 0.5 * elapsed) paces_.pop_front();
  const auto [since, doneThen] = paces_.front();
  const double pace = elapsed > since ? (done - doneThen) / (elapsed - since) : 0.0;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::string left = doneNow > 0.01 && done < 1.0
                               ? timeLeft(elapsed * (1.0 - done) / doneNow, pace > 0.0 ? (1.0 - done) / pace : nan)
                               : "";
  paces_.emplace_back(elapsed, done);
  if (mode_ == Mode::Log) {
    std::string stops;
    if (stop_.untilUnshot > 0.0) stops += fmt::format(" (until {:g}%)", 100.0 * stop_.untilUnshot);
    std::string c = showConvergence_ ? fmt::format("  C {:.4f}", r.convergence) : "";
    if (showConvergence_ && stop_.until < 1.0) c += fmt::format(" (until {:g})", stop_.until);
    fmt::print(out_, "unshot {:.2f}%{}{}  iteration {}  {:.1f} it/s{}\n", unshot, stops, c, r.iteration, rate, left);
  } else {
    // Within 80 columns, padded so that a shorter line overwrites the whole of a longer one.
    const int width = 12;
    const int filled = static_cast<int>(width * done);
    const std::string c = showConvergence_ ? fmt::format("  C {:.4f}", r.convergence) : "";
    const std::string text = fmt::format("unshot {:.2f}%{}  {} it  {:.0f} it/s{}", unshot, c, r.iteration, rate, left);
    fmt::print(out_, "\r[{}{}] {:<64}", std::string(filled, '#'), std::string(width - filled, '.'), text);
  }
  std::fflush(out_);
  lastPrintSeconds_ = elapsed;
  lastPrintedIteration_ = r.iteration;
}

void Progress::report(const IterationRecord& r, double elapsed) {
  const double interval = mode_ == Mode::Log ? kLogInterval : kTerminalInterval;
  if (lastPrintedIteration_ == 0 || elapsed - lastPrintSeconds_ >= interval) print(r, elapsed);
}

void Progress::resumeFrom(const IterationRecord& last) {
  startIteration_ = last.iteration;
  startDone_ = fractionDone(last);
}

void Progress::finish(const IterationRecord& last, double elapsed) {
  if (last.iteration != lastPrintedIteration_) print(last, elapsed);
  if (mode_ == Mode::Terminal) fmt::print(out_, "\n");
}

double solveWithProgress(ProgressiveSolver& solver, bool quiet, const std::function<void(double)>& afterStep) {
  Progress progress(solver.options());
  if (!solver.history().empty()) progress.resumeFrom(solver.history().back());
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  while (!solver.done() && !interrupted()) {
    const IterationRecord& record = solver.step();
    if (!quiet) progress.report(record, elapsed());
    if (afterStep) afterStep(elapsed());
  }
  if (!quiet && !solver.history().empty()) progress.finish(solver.history().back(), elapsed());
  return elapsed();
}

void warnAfterSolve(const Ledger& ledger, const SolveOptions& options, long long iterations, bool sceneClosed,
                    bool exactIterations) {
  if (const double unshot = ledger.unshotFraction(); unshot > kFarFromConvergedUnshot && !exactIterations) {
    // Said as what stopped it: the cap the user set is the one thing to change then.
    const std::string fix =
        iterations >= options.maxIterations
            ? fmt::format("--max-iterations {} stopped it: raise it, or leave it out to stop on what is left "
                          "(--until-unshot 0.01, the default)",
                          options.maxIterations)
            : "stop on what is left instead: --until 1 --until-unshot 0.01 (the default)";
    fmt::print(stderr,
               "radmesh: warning: the solve stopped with {:.1f}% of {} unshot, so its reflected light is far from "
               "converged (docs/accuracy.md); {}\n",
               100.0 * unshot, ledger.unshotBasis(), fix);
  }
  for (const std::string& warning : lostLightWarnings(ledger, sceneClosed))
    fmt::print(stderr, "radmesh: warning: {}\n", warning);
}

}  // namespace radmesh::cli
