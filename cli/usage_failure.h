#pragma once
// CLI11's own refusals in radmesh's words: "Could not convert: --resolution = x" and "A subcommand is
// required" name neither what was wrong nor what to give. Shared by radmesh and radmesh-view.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace radmesh::cli {

namespace usage_detail {

inline std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// The command the user reached: the deepest subcommand parsed, and its words ("radmesh bench").
inline const CLI::App* reached(const CLI::App* app, std::string& words) {
  for (;;) {
    const std::vector<CLI::App*> parsed = app->get_subcommands();
    if (parsed.empty()) return app;
    app = parsed.front();
    words += " " + app->get_name();
  }
}

// " (did you mean --projection?)" for a near miss of one of the command's options, or "".
inline std::string nearestOption(const CLI::App* app, const std::string& given) {
  std::string best;
  std::size_t bestDistance = given.size() / 3 + 1;  // a slip, not another word
  for (const CLI::Option* option : app->get_options()) {
    for (const std::string& name : option->get_lnames()) {
      const std::size_t distance = editDistance(given, "--" + name);
      if (distance < bestDistance) bestDistance = distance, best = "--" + name;
    }
  }
  return best.empty() ? "" : " (did you mean " + best + "?)";
}

// What an option's value is ("a list of whole numbers") and how to give it ("whole numbers separated by commas").
struct ValueKind {
  std::string noun, give;
};

inline ValueKind kindOfValue(const CLI::Option* option) {
  const std::string type = option ? option->get_type_name() : "";
  // The words an option takes, as its type name lists them ("auto|off"): "auto or off".
  if (const std::size_t bar = type.rfind('|'); bar != std::string::npos) {
    std::string words = type.substr(0, bar);
    std::replace(words.begin(), words.end(), '|', ',');
    words = CLI::detail::join(CLI::detail::split(words, ','), ", ") + " or " + type.substr(bar + 1);
    return {"one of " + words, words};
  }
  const bool list = option && option->get_expected_max() > 1;
  const bool whole = type.find("INT") != std::string::npos;
  const bool number = whole || type.find("FLOAT") != std::string::npos || type.find("NUMBER") != std::string::npos;
  const std::string one = !number ? "value" : whole ? "whole number" : "number";
  if (!list) return {"a " + one, "a " + one};
  return {"a list of " + one + "s", one + "s separated by commas"};
}

// The item of `value` (a comma list, as CLI11 gives it) that an int cannot hold, when every item is a
// whole number in decimal digits, or "": such a value is out of range, not "not a whole number".
// Every whole-number option of radmesh's is an int.
inline std::string outOfIntRange(const std::string& value) {
  std::string item, outside;
  std::stringstream items(value);
  while (std::getline(items, item, ',')) {
    const std::size_t digits = item.starts_with('+') || item.starts_with('-') ? 1 : 0;
    if (item.size() == digits || item.find_first_not_of("0123456789", digits) != std::string::npos) return "";
    // Leading zeros are gone (decimalArguments): more than 10 digits is past any int.
    if (outside.empty() && (item.size() - digits > 10 || std::stoll(item) < std::numeric_limits<int>::min() ||
                            std::stoll(item) > std::numeric_limits<int>::max()))
      outside = item;
  }
  return outside;
}

inline std::string between(const std::string& text, const std::string& after, const std::string& before) {
  const std::size_t start = text.find(after);
  if (start == std::string::npos) return "";
  const std::size_t from = start + after.size();
  const std::size_t end = before.empty() ? std::string::npos : text.find(before, from);
  return text.substr(from, end == std::string::npos ? std::string::npos : end - from);
}

}  // namespace usage_detail

// A CLI11 failure message for `program`: "<program>: error: ...", naming the option or word and what to give.
inline auto usageFailure(const std::string& program) {
  return [program](const CLI::App* app, const CLI::Error& e) -> std::string {
    using namespace usage_detail;
    std::string words = program;
    const CLI::App* command = reached(app, words);
    const std::string what = e.what();
    const std::string help = words + " --help";
    std::string message;
    if (what == "A subcommand is required" || what.rfind("Requires at least", 0) == 0) {
      std::vector<std::string> names;
      for (const CLI::App* s : command->get_subcommands([](const CLI::App*) { return true; })) names.push_back(s->get_name());
      const std::vector<std::string> left = command->remaining();
      message = (left.empty() ? words + " needs a command" : "'" + left.front() + "' is not a command of " + words) +
                ": give one of " + CLI::detail::join(names, ", ") + " (" + help + " says what each does)";
    } else if (const std::string name = between(what, "Could not convert: ", " = "); !name.empty()) {
      const CLI::Option* option = command->get_option_no_throw(name);
      const ValueKind kind = kindOfValue(option);
      const std::string value = between(what, " = ", "");
      if (const std::string outside = outOfIntRange(value); !outside.empty() && kind.noun.find("whole number") != std::string::npos)
        message = name + ": " + outside + " is out of range: a whole number here is from " +
                  std::to_string(std::numeric_limits<int>::min()) + " to " +
                  std::to_string(std::numeric_limits<int>::max()) + " (" + help + " says what " + name + " takes)";
      else
        message = name + ": " + value + " is not " + kind.noun + ": give " + kind.give + " (" + help + ")";
    } else if (what.find(" required ") != std::string::npos && what.find(" missing") != std::string::npos) {
      const std::string name = what.substr(0, what.find(':'));
      const CLI::Option* option = command->get_option_no_throw(name);
      message = name + " is given no value: give it " + kindOfValue(option).give + ", or leave it out";
    } else if (const std::string given = between(what, ": At Most 1 required but received ", ""); !given.empty()) {
      // An option given twice (list options take their values comma-separated, once).
      message = what.substr(0, what.find(':')) + " is given " + given + " times: give it once (" + help + ")";
    } else if (const std::string other = between(what, " excludes ", ""); !other.empty()) {
      message = what.substr(0, what.find(' ')) + " and " + other + " cannot be given together: give one of them (" +
                help + " says what each does)";
    } else if (const std::string extras = between(what, "not expected: ", ""); !extras.empty()) {
      // The words CLI11 could not place, which it lists last first; the first option among them is the slip.
      std::vector<std::string> left = CLI::detail::split(extras, ' ');
      std::reverse(left.begin(), left.end());
      const auto dashed = std::find_if(left.begin(), left.end(), [](const std::string& w) { return w.rfind("-", 0) == 0; });
      if (dashed != left.end())
        message = *dashed + " is not an option of " + words + nearestOption(command, *dashed) + ": " + help +
                  " lists them";
      else
        message = "'" + left.front() + "' is one argument too many for " + words + ": " + help + " says what it takes";
    } else {
      message = what + " (" + help + ")";
    }
    return program + ": error: " + message + "\n";
  };
}

}  // namespace radmesh::cli
