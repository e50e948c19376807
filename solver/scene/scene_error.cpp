#include "solver/scene/scene_error.h"

#include <cmath>

#include <fmt/format.h>

namespace radmesh {

namespace {

// A control byte in a quoted word (a stray ^A in '0.333^A3') prints as nothing or moves the cursor,
// leaving "'0.3333' is not a number": it is shown as \xNN. Line breaks stay (a reader's own
// messages may hold several lines).
std::string visible(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if ((byte < 0x20 && c != '\n' && c != '\t') || byte == 0x7f)
      out += fmt::format("\\x{:02x}", byte);
    else
      out += c;
  }
  return out;
}

std::string format(const std::string& file, const std::string& element, const std::string& problem,
                   const std::string& fix) {
  return visible(fmt::format("{}{}{}: {}{}{}{}", file, element.empty() ? "" : ": ", element, problem,
                             fix.empty() ? "" : " (fix: ", fix, fix.empty() ? "" : ")"));
}

}  // namespace

SceneError::SceneError(std::string file, std::string element, std::string problem, std::string fix)
    : std::runtime_error(format(file, element, problem, fix)),
      file_(std::move(file)),
      element_(std::move(element)) {}

void requireNonNegativeFactor(double value, const std::string& what, const std::string& file,
                              const std::string& element, const std::string& fix) {
  if (!(value >= 0.0 && std::isfinite(value)))
    throw SceneError(file, element, fmt::format("{} {} is negative or not finite", what, value), fix);
}

}  // namespace radmesh
