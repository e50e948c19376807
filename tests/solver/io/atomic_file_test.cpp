#include "solver/io/atomic_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "tests/solver/io/gltf_test_file.h"

namespace radmesh {
namespace {

std::string contentsOf(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The new bytes replace the old whole, and only the file itself is left in its folder.
TEST(AtomicFile, ReplacesTheFileWholeLeavingNothingBeside) {
  const test::TempDir dir;
  const std::string path = (dir / "state.bin").string();
  writeAtomically(path, "old state");
  writeAtomically(path, std::string("new\0state", 9));
  EXPECT_EQ(contentsOf(path), std::string("new\0state", 9));
  EXPECT_NO_THROW(checkWritableBeside(path));
  int files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, 1);
}

// A folder that does not exist: both name it, not the temporary file's name.
TEST(AtomicFile, AMissingFolderIsNamedWithTheReason) {
  const test::TempDir dir;
  const std::string path = (dir / "missing" / "state.bin").string();
  for (int check = 0; check < 2; ++check) {
    try {
      check ? checkWritableBeside(path) : writeAtomically(path, "state");
      ADD_FAILURE() << "wrote into a missing folder";
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      EXPECT_EQ(what, "the folder '" + (dir / "missing").string() + "' does not exist");
    }
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
}

}  // namespace
}  // namespace radmesh
