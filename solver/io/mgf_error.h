#pragma once
// What the MGF helpers throw for bad input. They know the problem and its fix but not where it
// happened; the interpreter (mgf_import.cpp) adds the file and line and rethrows a SceneError.
#include <stdexcept>
#include <string>

namespace radmesh {

class MgfError : public std::runtime_error {
 public:
  MgfError(const std::string& problem, std::string fix)
      : std::runtime_error(problem), fix_(std::move(fix)) {}
  const std::string& fix() const { return fix_; }

 private:
  std::string fix_;
};

}  // namespace radmesh
