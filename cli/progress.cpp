#include "cli/progress.h"

#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

namespace radmesh::cli {

namespace {

constexpr double kLogInterval = 1.0;        // seconds between lines in a log
constexpr double kTerminalInterval = 0.05;  // a live line redrawn at most 20 times a second

std::string duration(double seconds) {
  if (seconds < 60.0) return fmt::format("{:.0f} s", seconds);
  if (seconds < 3600.0) return fmt::format("{:.0f} min {:02.0f} s", std::floor(seconds / 60.0), std::fmod(seconds, 60.0));
  return fmt::format("{:.1f} h", seconds / 3600.0);
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
  // The pace over the latter half of the time so far: the unshot power falls fast under the first
  // shots and ever slower after, so the pace since the start would promise too early an end.
  if (paces_.empty()) paces_.emplace_back(0.0, startDone_);
  while (paces_.size() > 1 && paces_[1].first <= 0.5 * elapsed) paces_.pop_front();
  const auto [since, doneThen] = paces_.front();
  const double pace = elapsed > since ? (done - doneThen) / (elapsed - since) : 0.0;
  const std::string left =
      doneNow > 0.01 && done < 1.0 && pace > 0.0 ? fmt::format("  ~{} left", duration((1.0 - done) / pace)) : "";
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
  while (!solver.done()) {
    const IterationRecord& record = solver.step();
    if (!quiet) progress.report(record, elapsed());
    if (afterStep) afterStep(elapsed());
  }
  if (!quiet && !solver.history().empty()) progress.finish(solver.history().back(), elapsed());
  return elapsed();
}

void warnIfFarFromConverged(const Ledger& ledger) {
  const double unshot = ledger.unshotFraction();
  if (unshot <= kFarFromConvergedUnshot) return;
  fmt::print(stderr,
             "radmesh: warning: the solve stopped with {:.1f}% of the emitted power unshot, so its reflected light is "
             "far from converged (docs/accuracy.md); stop on what is left instead: --until 1 --until-unshot 0.01 "
             "(the default)\n",
             100.0 * unshot);
}

}  // namespace radmesh::cli
