#pragma once
// Progress a person can read: on a terminal, one live line per solve (a bar toward the stopping
// rule, the unshot power, C, iterations per second and the time left, redrawn with \r); in a pipe
// or a log, a line every second (and the final one), not one per iteration.
#include <cstdio>
#include <deque>
#include <functional>
#include <utility>

#include "solver/radiosity/progressive_solver.h"

namespace radmesh::cli {

class Progress {
 public:
  enum class Mode { Terminal, Log };
  // The mode follows `out`: a terminal gets the live line.
  explicit Progress(const SolveOptions& stop, std::FILE* out = stdout);
  Progress(const SolveOptions& stop, std::FILE* out, Mode mode);
  // `elapsedSeconds` since the solve began: the caller's clock, so that tests can inject one.
  void report(const IterationRecord& record, double elapsedSeconds);
  void finish(const IterationRecord& last, double elapsedSeconds);  // the final line
  // A solve resumed after `last` (a checkpoint): the rate and the time left count only the
  // iterations and progress made since, as the elapsed time does.
  void resumeFrom(const IterationRecord& last);
  // A cells solve's lines: no C, which is not defined across cells.
  void withoutConvergence() { showConvergence_ = false; }

 private:
  void print(const IterationRecord& record, double elapsedSeconds);
  double fractionDone(const IterationRecord& record) const;

  SolveOptions stop_;
  std::FILE* out_;
  Mode mode_;
  double lastPrintSeconds_ = 0.0;
  int lastPrintedIteration_ = 0;
  int startIteration_ = 0;
  double startDone_ = 0.0;
  bool showConvergence_ = true;
  // (elapsed seconds, fractionDone) at each line printed, from the latest one at or before half
  // the time so far: the recent pace, beside the average since the start, for the time left.
  std::deque<std::pair<double, double>> paces_;
};

// Steps `solver` until done(), with progress on stdout unless `quiet`, calling afterStep (if any)
// with the wall seconds so far after each step; returns the wall seconds.
double solveWithProgress(ProgressiveSolver& solver, bool quiet,
                         const std::function<void(double seconds)>& afterStep = {});

// On stderr, what a finished solve's ledger says is wrong with it: more than
// kFarFromConvergedUnshot of the power left unshot, saying what to change (--max-iterations where
// `iterations` reached it, else the stop; not said when `exactIterations`, render's --iterations,
// asked for that count), and each of lostLightWarnings (`sceneClosed`: isClosed of the scene).
// solve and render both end with it.
void warnAfterSolve(const Ledger& ledger, const SolveOptions& options, long long iterations, bool sceneClosed,
                    bool exactIterations = false);

}  // namespace radmesh::cli
