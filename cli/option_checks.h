#pragma once
// Option checks whose refusals say what to give: CLI11's PositiveNumber names its range as "0.000000
// to 17976931348623157...", the largest double written out in full.
#include <CLI/CLI.hpp>
#include <string>

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

}  // namespace radmesh::cli
