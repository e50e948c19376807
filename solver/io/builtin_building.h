#pragma once
// `building:COLSxROWS`: a generated office building for scale (docs/scenes.md): rows of rooms on
// corridors, doors, windows, furniture and ceiling lights, about one room per unit.
#include <string>

#include "solver/scene/scene.h"

namespace radmesh {

inline constexpr const char* kBuildingPrefix = "building:";

// What the generator makes, so that tests and tools can check a partition against it.
struct BuildingLayout {
  int cols = 0;
  int rows = 0;
  int rooms() const { return cols * rows; }
  int wings() const { return (rows + 1) / 2; }  // a corridor with a row of rooms on each side
  int corridors() const { return wings() + 1; }  // the wings' corridors and the spine joining them
  int doors() const { return rooms() + wings(); }  // each room's, and each wing corridor's onto the spine
};

// "building:10x10" -> {10, 10}. Throws SceneError for a name that is not of that form or asks
// for more than kBuildingMaxUnits rooms in a row or column.
BuildingLayout parseBuildingName(const std::string& name);
inline constexpr int kBuildingMaxUnits = 100;

// The room names the generator gives (each room's polygons carry it: "room 'NAME' ...").
std::string buildingRoomName(int col, int row);
std::string buildingCorridorName(int wing);
inline constexpr const char* kBuildingSpineName = "spine";

Scene buildingScene(const BuildingLayout& layout);

}  // namespace radmesh
