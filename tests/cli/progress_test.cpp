// Progress lines a person can read: bounded in a log, one redrawn line on a terminal. The clock
// is injected (elapsed seconds per report), so nothing here depends on timing.
#include "cli/progress.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>

namespace radmesh::cli {
namespace {

// What `feed` makes a Progress print, stopping at 1 % unshot.
std::string printed(Progress::Mode mode, const std::function<void(Progress&)>& feed) {
  SolveOptions stop;
  stop.until = 1.0;
  stop.untilUnshot = 0.01;
  std::FILE* out = std::tmpfile();
  Progress progress(stop, out, mode);
  feed(progress);
  std::string text(static_cast<size_t>(std::ftell(out)), '\0');
  std::rewind(out);
  text.resize(std::fread(text.data(), 1, text.size(), out));
  std::fclose(out);
  return text;
}

// What `reports` iterations print, iteration i at i/1024 s (exact in binary).
std::string progressText(Progress::Mode mode, int reports) {
  return printed(mode, [&](Progress& progress) {
    IterationRecord r;
    r.ledger.emitted = 1.0;
    for (int i = 1; i <= reports; ++i) {
      r.iteration = i;
      r.convergence = 1.0 - 1.0 / i;
      r.ledger.unshot = 1.0 / i;
      progress.report(r, i / 1024.0);
    }
    progress.finish(r, reports / 1024.0);
  });
}

TEST(Progress, LogPrintsALineASecondAndTheFinalOne) {
  // 10240 iterations in 10 s: the first, one a second after it (iterations 1025 ... 9217), the last.
  const std::string text = progressText(Progress::Mode::Log, 10240);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 11) << text;
  EXPECT_EQ(text.find('\r'), std::string::npos);
  EXPECT_NE(text.find("iteration 1025 "), std::string::npos) << text;
  EXPECT_NE(text.find("iteration 10240 "), std::string::npos) << text;
  // Each line carries the unshot power against its target and C.
  EXPECT_NE(text.find("unshot 0.01% (until 1%)  C 0.9999  iteration 10240  1024.0 it/s"), std::string::npos)
      << text;
}

// A cells solve has no C: its lines leave it out, in a log and on a terminal.
TEST(Progress, WithoutConvergenceLeavesCOut) {
  for (const Progress::Mode mode : {Progress::Mode::Log, Progress::Mode::Terminal}) {
    const std::string text = printed(mode, [](Progress& progress) {
      progress.withoutConvergence();
      IterationRecord r;
      r.ledger.emitted = 1.0;
      r.ledger.unshot = 0.5;
      r.iteration = 10;
      progress.report(r, 1.0);
      progress.finish(r, 1.0);
    });
    EXPECT_EQ(text.find(" C "), std::string::npos) << text;
    EXPECT_NE(text.find("unshot 50.00%"), std::string::npos) << text;
  }
}

TEST(Progress, TerminalRedrawsOneLineAndEndsIt) {
  const std::string text = progressText(Progress::Mode::Terminal, 10240);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1);
  EXPECT_EQ(text.back(), '\n');
  // At most 20 redraws a second over 10 s, and the last one shows the last iteration, bar full.
  const auto redraws = std::count(text.begin(), text.end(), '\r');
  EXPECT_GE(redraws, 100);
  EXPECT_LE(redraws, 202);
  const size_t last = text.rfind('\r');
  EXPECT_EQ(text.substr(last), "\r[############] unshot 0.01%  C 0.9999  10240 it  1024 it/s" + std::string(21, ' ') + "\n");
  EXPECT_EQ(text.size() - last, 1u + 15u + 64u + 1u);  // 79 columns: within a terminal of 80
}

TEST(Progress, EstimatesTheTimeLeftFromTheUnshotPowerOnALogScale) {
  // Halfway on a log scale (10 % unshot of a 1 % target) after 2 s: about 2 s left.
  const std::string text = printed(Progress::Mode::Log, [](Progress& progress) {
    IterationRecord r;
    r.iteration = 100;
    r.ledger.emitted = 1.0;
    r.ledger.unshot = 0.1;
    progress.report(r, 2.0);
  });
  EXPECT_NE(text.find("~2 s left"), std::string::npos) << text;
}

// The unshot power falls fast under the first shots and slowly after: the time left at the pace of
// the latter half of the run is given beside the one at the average pace since the start.
TEST(Progress, GivesTheTimeLeftAtTheRecentPaceBesideTheAverage) {
  const std::string text = printed(Progress::Mode::Log, [](Progress& progress) {
    IterationRecord r;
    r.ledger.emitted = 1.0;
    // Done (on the log scale to 1 %): 0.5 at 1 s, 0.6 at 10 s, 0.62 at 20 s.
    for (const auto& [seconds, done] : {std::pair{1.0, 0.5}, {10.0, 0.6}, {20.0, 0.62}}) {
      r.iteration = static_cast<int>(seconds * 100);
      r.ledger.unshot = std::pow(0.01, done);
      progress.report(r, seconds);
    }
  });
  // At 10 s: 0.1 in the last 9 s, 0.4 more in 36 s; the average, 0.6 in 10 s, says 7 s: a range.
  EXPECT_NE(text.find("iteration 1000  100.0 it/s  ~7-36 s left"), std::string::npos) << text;
  // From 10 s to 20 s: 0.02 in 10 s, so 0.38 more takes 190 s; the average, 0.62 in 20 s, 12 s.
  EXPECT_NE(text.find("iteration 2000  100.0 it/s  ~12 s to 3 min left"), std::string::npos) << text;
}

TEST(Progress, GivesOneTimeLeftWhereTheTwoPacesPrintAlike) {
  const std::string text = printed(Progress::Mode::Log, [](Progress& progress) {
    IterationRecord r;
    r.ledger.emitted = 1.0;
    for (const auto& [seconds, done] : {std::pair{1.0, 0.5}, {2.0, 0.72}}) {
      r.iteration = static_cast<int>(seconds * 100);
      r.ledger.unshot = std::pow(0.01, done);
      progress.report(r, seconds);
    }
  });
  // At 2 s the average says 0.78 s and the last second's pace 1.27 s: both "1 s", not "~1-1 s".
  EXPECT_NE(text.find("iteration 200  100.0 it/s  ~1 s left\n"), std::string::npos) << text;
}

TEST(Progress, AResumedSolveCountsOnlyTheIterationsAndProgressSinceTheCheckpoint) {
  // Resumed at iteration 1000 with 10 % unshot (halfway to 1 % on a log scale). 1 s and 100
  // iterations later, at 3.16 % (three quarters): 100 it/s, and a quarter took 1 s, so ~1 s left.
  const std::string text = printed(Progress::Mode::Log, [](Progress& progress) {
    IterationRecord r;
    r.iteration = 1000;
    r.ledger.emitted = 1.0;
    r.ledger.unshot = 0.1;
    progress.resumeFrom(r);
    r.iteration = 1100;
    r.ledger.unshot = std::pow(10.0, -1.5);
    progress.report(r, 1.0);
  });
  EXPECT_NE(text.find("iteration 1100  100.0 it/s  ~1 s left"), std::string::npos) << text;
}

}  // namespace
}  // namespace radmesh::cli
