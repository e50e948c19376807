#pragma once
// Option checks whose refusals say what to give: CLI11's PositiveNumber names its range as "0.000000
// to 17976931348623157...", the largest double written out in full.
#include <CLI/CLI.hpp>
#include <array>
#include <cstdio>
#include <optional>
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
        return text + (number ? " is not " + bound : std::string(" is not a number")) + ": give a number " + bound;
      },
      inclusive ? "NONNEGATIVE" : "POSITIVE");
}

// WxH (--size) with each side in [least, most], or nullopt: every character read (640x480junk is no
// size), no overflow (99999999999 is no side).
inline std::optional<std::array<int, 2>> parseSize(const std::string& text, int least, int most) {
  std::array<int, 2> size{};
  const std::size_t x = text.find('x');
  if (x == std::string::npos) return std::nullopt;
  const std::string sides[2] = {text.substr(0, x), text.substr(x + 1)};
  for (int i = 0; i < 2; ++i) {
    if (sides[i].empty() || sides[i].size() > 9 || sides[i].find_first_not_of("0123456789") != std::string::npos)
      return std::nullopt;
    size[i] = std::stoi(sides[i]);
    if (size[i] < least || size[i] > most) return std::nullopt;
  }
  return size;
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
        return text + " is not a thread count: give 0 (" +
               (std::string(program) == "radmesh-view" ? "every core but one, left to drawing" : "every core") +
               ") or a positive count";
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

// CLI11 reads an empty value as 0 for a number (--cache-mb "" would turn the cache off), and no
// option here means anything by one: the option given an empty value ("" or --option=), or "".
inline std::string optionWithEmptyValue(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.empty()) return i > 1 ? argv[i - 1] : "the first argument";
    if (arg.rfind("--", 0) == 0 && arg.back() == '=') return arg.substr(0, arg.size() - 1);
  }
  return "";
}

}  // namespace radmesh::cli
