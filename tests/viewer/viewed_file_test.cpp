// What radmesh-view reads of a file, at launch and when the panel's Open field or a drop names
// another: scenes with their cell chosen, bakes as they are, and files that cannot be read refused
// by name (the window then keeps the scene it shows).
#include "viewer/viewed_file.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "solver/meshing/meshing.h"
#include "solver/scene/scene_error.h"
#include "tests/test_paths.h"

namespace radmesh {
namespace {

bool hasNote(const ViewedFile& file, const std::string& text) {
  return std::find(file.notes.begin(), file.notes.end(), text) != file.notes.end();
}

TEST(ViewedFile, AScenesCellIsChosenFromItsSizeUnlessGiven) {
  ViewerArgs args;
  const ViewedFile chosen = readViewedFile("cornell", args);
  EXPECT_FALSE(chosen.bake);
  const CellChoice cell = chooseCell(chosen.scene);
  EXPECT_EQ(chosen.setup.cellM, cell.cellM);
  EXPECT_TRUE(hasNote(chosen, cell.why));
  EXPECT_EQ(chosen.setup.options.backend, args.setup.options.backend);  // the rest is the launch's

  args.cellGiven = true;
  args.setup.cellM = 0.2;
  const ViewedFile given = readViewedFile("cornell", args);
  EXPECT_EQ(given.setup.cellM, 0.2);
  EXPECT_FALSE(hasNote(given, cell.why));
}

// --preset elements: each scene opened gets patches 2.625 times its own cell (rounded) and elements
// a quarter of those, as radmesh solve's preset makes them.
TEST(ViewedFile, ThePresetElementsSizesEachScenesPatchesAndElements) {
  ViewerArgs args;
  args.elementsPreset = true;
  args.setup.options.subdivide = Subdivide::Uniform;
  for (const auto& [scene, cellM] : {std::pair{"office", 1.0}, {"cornell", 0.09}}) {
    const ViewedFile file = readViewedFile(scene, args);
    EXPECT_DOUBLE_EQ(file.setup.cellM, cellM) << scene;
    EXPECT_DOUBLE_EQ(file.setup.options.minElementM, 0.25 * cellM) << scene;
    EXPECT_TRUE(hasNote(file, fmt::format("cell {:.4g} m, --preset elements' 2.625 x the scene's, rounded: {}", cellM,
                                          chooseCell(file.scene).why)))
        << scene;
  }
  args.cellGiven = true;  // --cell sizes the patches; the elements still follow
  args.setup.cellM = 0.2;
  const ViewedFile given = readViewedFile("cornell", args);
  EXPECT_EQ(given.setup.cellM, 0.2);
  EXPECT_DOUBLE_EQ(given.setup.options.minElementM, 0.05);
}

TEST(ViewedFile, ABakeIsWalkedAsItIsWithItsGeometryForTheFrame) {
  const std::string path = test::dataPath("other_tool_bake.gltf").string();
  const ViewedFile file = readViewedFile(path, ViewerArgs{});
  ASSERT_TRUE(file.bake);
  EXPECT_FALSE(file.bake->fromRadmesh);
  EXPECT_FALSE(file.scene.polygons.empty());
  EXPECT_EQ(file.bake->upAxis, file.scene.upAxis);
  EXPECT_EQ(file.path, path);
}

TEST(ViewedFile, WhatTheReaderRepairsIsCountedAsWarnings) {
  const ViewedFile file = readViewedFile(test::dataPath("repaired/mgf_unknown_entity.mgf").string(), ViewerArgs{});
  EXPECT_FALSE(file.warnings.empty());
}

TEST(ViewedFile, AFileThatCannotBeReadIsRefusedByName) {
  for (const std::string name : {"bad/gltf_truncated.gltf", "bad/mgf_nan.mgf", "no_such_file.gltf"}) {
    const std::string path = test::dataPath(name).string();
    try {
      readViewedFile(path, ViewerArgs{});
      ADD_FAILURE() << name << " was read";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(name.substr(name.find('/') + 1)), std::string::npos) << e.what();
    }
  }
}

// The panel's Open error says the path once ("could not open X: X: no such file" it said).
TEST(ViewedFile, AFileThatCannotBeOpenedIsNamedOnce) {
  const std::string path = test::dataPath("no_such_file.gltf").string();
  try {
    readViewedFile(path, ViewerArgs{});
    ADD_FAILURE() << path << " was read";
  } catch (const SceneError& e) {
    EXPECT_EQ(openFailure(path, e.what()),
              "could not open " + path +
                  ": no such file, and not a built-in scene name (fix: give a .gltf, .glb or .mgf file, or a built-in "
                  "scene name (office, cornell, furnace, two-rooms, building:COLSxROWS))");
  }
  // An error that does not name it is given the path.
  EXPECT_EQ(openFailure("a.glb", "out of memory"), "could not open a.glb: out of memory");
}

}  // namespace
}  // namespace radmesh
