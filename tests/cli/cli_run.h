#pragma once
// Running the built `radmesh` as a user would, and a temporary folder per test.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

#include "tests/test_paths.h"

namespace radmesh {

struct CommandRun {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

inline CommandRun radmesh(const std::string& arguments) {
  const std::string command = (test::binaryDir() / "cli" / "radmesh").string() + " " + arguments + " 2>&1";
  CommandRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  std::array<char, 4096> buffer{};
  while (size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) run.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

inline std::string tempPath(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("radmesh-cli-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

}  // namespace radmesh
