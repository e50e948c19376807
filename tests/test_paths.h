#pragma once
// Paths the tests use: the project's own files, and ../shared beside the project, which CI always
// has and a user's clone may not (tests that need it skip, saying so).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace radmesh::test {

inline std::filesystem::path sourceDir() { return RADMESH_SOURCE_DIR; }
inline std::filesystem::path binaryDir() { return RADMESH_BINARY_DIR; }
inline std::filesystem::path dataPath(const std::string& relative) {
  return sourceDir() / "tests" / "data" / relative;
}
inline std::filesystem::path sharedDir() { return sourceDir().parent_path() / "shared"; }

// The path of a file under ../shared, or an empty path when ../shared is absent.
inline std::filesystem::path sharedPath(const std::string& relative) {
  auto p = sharedDir() / relative;
  return std::filesystem::exists(p) ? p : std::filesystem::path{};
}

}  // namespace radmesh::test

// Skips the current test when a ../shared file is missing (a user's clone), naming what is missing.
#define RADMESH_REQUIRE_SHARED(var, relative)                                                  \
  const std::filesystem::path var = ::radmesh::test::sharedPath(relative);                    \
  if (var.empty())                                                                             \
  GTEST_SKIP() << "../shared/" << (relative)                                                   \
               << " is absent (it ships beside the project in CI, not in a user's clone)"
