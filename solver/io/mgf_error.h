#pragma once
// What the MGF helpers throw for bad input. They know the problem and its fix but not where it
// happened; the interpreter (mgf_import.cpp) adds the file and line and rethrows a SceneError.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "solver/scene/scene.h"

namespace radmesh {

class MgfError : public std::runtime_error {
 public:
  MgfError(const std::string& problem, std::string fix)
      : std::runtime_error(printable(problem)), fix_(std::move(fix)) {}
  const std::string& fix() const { return fix_; }

 private:
  std::string fix_;

  // A NUL byte quoted from a binary file would end what() there: it is shown as \0.
  static std::string printable(const std::string& text) {
    std::string out;
    for (char c : text) out += c == '\0' ? std::string("\\0") : std::string(1, c);
    return out;
  }
};

// A point farther from the origin than kMaxCoordinate is refused where it is given or placed, not
// dropped later as degenerate.
inline void checkMgfPoint(const Vec3& p, const std::string& what, const std::string& fix) {
  if (!withinCoordinateBound(p))
    throw MgfError(fmt::format("{} ({:g}, {:g}, {:g}) is farther than {:g} from the origin", what, p.x, p.y, p.z,
                               kMaxCoordinate),
                   fix);
}

}  // namespace radmesh
