#pragma once
// Small MGF scenes written at test time into a per-test temporary directory, and the sums the MGF
// tests check them by.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "solver/io/mgf_import.h"
#include "tests/solver/io/gltf_test_file.h"  // TempDir

namespace radmesh::test {

// Writes `text` as `name` in `dir` (creating sub-folders) and returns its path.
inline std::string writeMgf(const TempDir& dir, const std::string& name, const std::string& text) {
  const std::filesystem::path path = dir / name;
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << text;
  return path.string();
}

// Imports `text` as a one-file scene.
inline Scene importMgfText(const std::string& text, std::vector<std::string>* warnings = nullptr) {
  TempDir dir;
  return importMgf(writeMgf(dir, "scene.mgf", text), warnings);
}

// A material with a light and a unit square face, in the plane z = 0, facing +z.
inline const std::string kUnitSquare =
    "m light =\n  ed 100\n"
    "v a =\n  p 0 0 0\nv b =\n  p 1 0 0\nv c =\n  p 1 1 0\nv d =\n  p 0 1 0\n";

}  // namespace radmesh::test
