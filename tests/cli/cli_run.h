#pragma once
// Running the built `radmesh` as a user would, and a temporary folder per test.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/test_paths.h"

namespace radmesh {

struct CommandRun {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

// Runs a shell command line, its stderr with its stdout.
inline CommandRun runCommand(const std::string& commandLine) {
  const std::string command = commandLine + " 2>&1";
  CommandRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  std::array<char, 4096> buffer{};
  while (size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) run.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

inline CommandRun radmesh(const std::string& arguments) {
  return runCommand((test::binaryDir() / "cli" / "radmesh").string() + " " + arguments);
}

// The folders tempPath made in this process: emptied when first used (a folder left by an earlier
// run whose process had the same id would hold its files) and removed when the process ends.
class TempFolders {
 public:
  ~TempFolders() {
    std::error_code ignored;
    for (const std::filesystem::path& dir : made_) std::filesystem::remove_all(dir, ignored);
  }
  const std::filesystem::path& fresh(const std::filesystem::path& dir) {
    for (const std::filesystem::path& made : made_)
      if (made == dir) return made;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return made_.emplace_back(dir);
  }

 private:
  std::vector<std::filesystem::path> made_;
};

// A folder per test and process: other checkouts may run the same tests at the same time.
inline std::string tempPath(const std::string& name) {
  static TempFolders folders;
  const auto dir = std::filesystem::temp_directory_path() /
                   ("radmesh-cli-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
                    "-" + std::to_string(getpid()));
  return (folders.fresh(dir) / name).string();
}

// The start of a command line running its program in a virtual X display, or empty without
// xvfb-run. Each process starts its search for a free server number at its own: xvfb-run -a alone
// starts every one at 99, and two tests at once raced for it (one failed as it cleaned up). The
// X authority file is the test's own: left to itself, xvfb-run makes a folder for one and now and
// then fails to remove it after the command, exiting 5 in place of the command's own status.
inline std::string virtualDisplay(const std::string& screen = "1280x720x24") {
  if (std::system("command -v xvfb-run > /dev/null") != 0) return {};
  return "xvfb-run -a -n " + std::to_string(100 + getpid() % 800) + " -f " + tempPath("Xauthority") +
         " -s '-screen 0 " + screen + "' ";
}

// The plots are drawn by gnuplot where it is installed (scripts/install-deps.sh installs it).
inline bool gnuplotInstalled() { return std::system("command -v gnuplot > /dev/null 2>&1") == 0; }

inline std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline nlohmann::json readJson(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// The JSON a command printed, after what went to stderr (warnings come first).
inline nlohmann::json jsonOf(const CommandRun& run) {
  const std::size_t at = run.output.find('{');
  return nlohmann::json::parse(at == std::string::npos ? std::string() : run.output.substr(at), nullptr, false);
}

// `radmesh info <arguments> --json`'s figures; the command must succeed.
inline nlohmann::json infoJson(const std::string& arguments) {
  const CommandRun run = radmesh("info " + arguments + " --json");
  EXPECT_EQ(run.exitCode, 0) << run.output;
  return jsonOf(run);
}

// What `radmesh bench` printed and the JSON it wrote.
struct BenchRun {
  std::string output;
  nlohmann::json json;
};

// Runs `radmesh bench <arguments> --json <file>`, which must succeed. A run that fails without
// writing its JSON ends the test: the file is removed first, so parse throws.
inline BenchRun runBench(const std::string& arguments) {
  const std::string json = tempPath("bench.json");
  std::filesystem::remove(json);
  const CommandRun run = radmesh("bench " + arguments + " --json " + json);
  EXPECT_EQ(run.exitCode, 0) << run.output;
  return {run.output, nlohmann::json::parse(std::ifstream(json))};
}

// Width and height from a PNG's IHDR chunk (big-endian, bytes 16..23).
inline std::pair<int, int> pngSize(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<unsigned char, 24> head{};
  in.read(reinterpret_cast<char*>(head.data()), head.size());
  if (!in || head[1] != 'P' || head[2] != 'N' || head[3] != 'G') return {-1, -1};
  auto be = [&](int at) { return (head[at] << 24) | (head[at + 1] << 16) | (head[at + 2] << 8) | head[at + 3]; };
  return {be(16), be(20)};
}

}  // namespace radmesh
