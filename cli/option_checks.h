#pragma once
// Option checks whose refusals say what to give: CLI11's PositiveNumber names its range as "0.000000
// to 17976931348623157...", the largest double written out in full.
#include <CLI/CLI.hpp>
#include <array>
#include <cstdio>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli/usage_failure.h"
#include "parallel/thread_pool.h"
#include "solver/scene/scene_error.h"

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

// A name the outputs take as their file stem (NAME.csv beside NAME-traces.csv in --out-dir): one
// file name, not a path ("a/b" had written into a folder a/), and not "." or "..".
inline const CLI::Validator kFileStem(
    [](std::string& text) -> std::string {
      if (!text.empty() && text != "." && text != ".." && text.find('/') == std::string::npos) return {};
      return "'" + text + "' is not a file name: give a name without '/' (the outputs go to --out-dir)";
    },
    "STEM");

inline const CLI::Validator kPositive = numberAbove(0.0);
inline const CLI::Validator kNonNegative = numberAbove(0.0, true);

// --threads: 0 (every core) or a count, at most ThreadPool::mostUseful(), the machine's hardware
// threads. More only wait for a core, each holding its own scratch (a patch index per patch), so
// they are cut to that many, with a warning under the program's name.
inline CLI::Validator threadCount(const char* program) {
  return CLI::Validator(
    [program](std::string& text) -> std::string {
      int value = 0;
      if (!CLI::detail::lexical_cast(text, value) || value < 0)
        return text + " is not a thread count: give 0 (" +
               (std::string(program) == "radmesh-view" ? "every core but one, left to drawing" : "every core") +
               ") or a positive count";
      const int hardware = ThreadPool::mostUseful();
      if (value > hardware) {
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

// The arguments with every whole-number option's value read as decimal. CLI11 converts whole
// numbers with strtoll's base 0, so "--resolution 064" gave 52 (octal) and "0x10" 16; a leading
// zero is dropped here, and another base is refused (OptionError) naming the option. The options
// are those of `app` and of the subcommands the arguments name; values may be comma lists.
// An option that takes a value followed by another option ("--cells --threads 1") is refused here
// naming it and what it takes: CLI11 always eats a value, so it took "--threads" as the value and
// then refused the "1" left over as one argument too many.
// Returned in the reversed order app.parse(std::vector<std::string>&) takes.
inline std::vector<std::string> decimalArguments(const CLI::App& app, int argc, char** argv) {
  std::set<std::string> whole;
  const auto collect = [&whole](const CLI::App& a) {
    for (const CLI::Option* o : a.get_options())
      if (o->get_type_name().rfind("INT", 0) == 0 || o->get_type_name().rfind("UINT", 0) == 0)
        for (const std::string& name : o->get_lnames()) whole.insert("--" + name);
  };
  collect(app);
  const CLI::App* current = &app;
  std::vector<std::string> args(argv + 1, argv + argc);
  const auto decimal = [](const std::string& option, const std::string& value) {
    std::string out, item;
    std::stringstream items(value);
    while (std::getline(items, item, ',')) {
      const size_t digits = item.find_first_not_of("+-");
      if (digits != std::string::npos && item.size() > digits + 1 && item[digits] == '0') {
        if (item.find_first_not_of("0123456789", digits) != std::string::npos)
          throw OptionError(option + ": " + value + " is not a whole number in decimal digits: give it in decimal");
        const size_t first = std::min(item.find_first_not_of('0', digits), item.size() - 1);
        item = item.substr(0, digits) + item.substr(first);
      }
      out += (out.empty() ? "" : ",") + item;
    }
    return value.empty() ? value : out;
  };
  for (size_t i = 0; i < args.size(); ++i) {
    std::string& arg = args[i];
    if (arg.rfind("--", 0) != 0) {
      for (const CLI::App* sub : current->get_subcommands({}))
        if (sub->check_name(arg)) {
          current = sub;
          collect(*sub);
        }
      continue;
    }
    const size_t equals = arg.find('=');
    const std::string name = arg.substr(0, equals);
    if (equals == std::string::npos && i + 1 < args.size() && args[i + 1].rfind("--", 0) == 0 && args[i + 1].size() > 2) {
      const CLI::Option* option = nullptr;
      for (const CLI::App* a = current; a && !option; a = a->get_parent()) option = a->get_option_no_throw(name);
      if (option && option->get_expected_min() > 0 && option->get_type_size_min() > 0)
        throw OptionError(name + " is given no value (" + args[i + 1] + ", after it, is an option): give it " +
                          usage_detail::kindOfValue(option).give + ", or leave it out");
    }
    if (!whole.count(name)) continue;
    if (equals != std::string::npos)
      arg = name + "=" + decimal(name, arg.substr(equals + 1));
    else if (i + 1 < args.size())
      args[i + 1] = decimal(name, args[i + 1]);
  }
  return {args.rbegin(), args.rend()};
}

}  // namespace radmesh::cli
