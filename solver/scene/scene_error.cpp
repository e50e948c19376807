#include "solver/scene/scene_error.h"

#include <cmath>

#include <fmt/format.h>

namespace radmesh {

namespace {
std::string format(const std::string& file, const std::string& element, const std::string& problem,
                   const std::string& fix) {
  return fmt::format("{}{}{}: {}{}{}{}", file, element.empty() ? "" : ": ", element, problem, fix.empty() ? "" : " (fix: ",
                     fix, fix.empty() ? "" : ")");
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
