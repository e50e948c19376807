#pragma once
// Bad input is the user's to fix: a SceneError names the file, the element and the fix.
// Broken invariants inside radmesh are not SceneErrors (they are bugs, reported as SolveErrors).
#include <stdexcept>
#include <string>

namespace radmesh {

class SceneError : public std::runtime_error {
 public:
  // file: the path (or built-in name); element: what in it, e.g. "line 12: f" or "mesh 'desk'
  // primitive 0"; problem: what is wrong; fix: what the user can do about it.
  SceneError(std::string file, std::string element, std::string problem, std::string fix);

  const std::string& file() const { return file_; }
  const std::string& element() const { return element_; }

 private:
  std::string file_;
  std::string element_;
};

// Refuses a factor of light (an intensity, a colour channel, an emission factor) that is negative
// or not finite, by name: checking only a product would let two negative factors pass as light.
void requireNonNegativeFactor(double value, const std::string& what, const std::string& file,
                              const std::string& element, const std::string& fix);

// Refused options (an impossible --cell, --resolution out of range, ...): named option and fix.
class OptionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The solve's own numbers went wrong (the energy ledger stopped balancing, an unshot power became
// NaN): a fault in radmesh or a back end, not in the input. Nothing computed from them is written.
class SolveError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace radmesh
