#pragma once
// Option checks whose refusals say what to give: CLI11's PositiveNumber names its range as "0.000000
// to 17976931348623157...", the largest double written out in full.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <thread>

namespace radmesh::cli {

// A number above `least` (or, `inclusive`, at least it): "--steps: 0 is not above 0: give a number above 0".
inline CLI::Validator numberAbove(double least, bool inclusive = false) {
  const std::string bound = (inclusive ? "at least " : "above ") + CLI::detail::to_string(least);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double value = 0.0;
        const bool number = CLI::detail::lexical_cast(text, value);
        if (number && (inclusive ? value >= least : value > least)) return {};
        return text + " is not " + bound + ": give a number " + bound;
      },
      inclusive ? "NONNEGATIVE" : "POSITIVE");
}

inline const CLI::Validator kPositive = numberAbove(0.0);
inline const CLI::Validator kNonNegative = numberAbove(0.0, true);

// --threads: 0 (every core) or a count, at most the machine's hardware threads. More only wait
// for a core, each holding its own scratch (a patch index per patch), so they are cut to that
// many, with a warning under the program's name.
inline CLI::Validator threadCount(const char* program) {
  return CLI::Validator(
    [program](std::string& text) -> std::string {
      int value = 0;
      if (!CLI::detail::lexical_cast(text, value) || value < 0)
        return text + " is not a thread count: give 0 (every core) or a positive count";
      const int hardware = static_cast<int>(std::thread::hardware_concurrency());
      if (hardware > 0 && value > hardware) {
        std::fprintf(stderr, "%s: warning: --threads %d is more than the %d this machine runs at once: using %d\n",
                     program, value, hardware, hardware);
        text = std::to_string(hardware);
      }
      return {};
    },
    "THREADS");
}

}  // namespace radmesh::cli
