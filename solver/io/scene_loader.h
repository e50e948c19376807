#pragma once
// One entry point for every command that takes a SCENE: a built-in name or a .gltf/.glb/.mgf path.
#include <string>
#include <vector>

#include "solver/io/daylight.h"
#include "solver/scene/scene.h"
#include "solver/scene/up_axis.h"

namespace radmesh {

inline constexpr const char* kDefaultScene = "office";

// ".glb" for "Office.GLB": the extension, with its dot, in lower case ("" for none).
std::string lowerCaseExtension(const std::string& path);

// Throws SceneError unless `path` is a regular file that may hold a scene: not missing, a folder,
// a pipe or a device, nor a radmesh checkpoint whatever its name.
void checkSceneFile(const std::string& path);

// Loads, scales to metres (`metresPerUnit`, --units: solver/scene/units.h; 0, not given, reads
// metres), turns by `up` (by default the format's axis, and for MGF, which does not say, --up
// auto's guess: solver/scene/up_axis.h), lights by `daylight` (its sky at the openings, what that
// added a line each in `notes`; its sun among the scene's lights, north along the up frame's
// `along`), and validates; throws SceneError with file, element and fix on anything unusable.
// `readNotes` gets a line for each guess about how the file is drawn: the axis when it was guessed,
// and the units when a model read in metres is over a kilometre across.
Scene loadScene(const std::string& pathOrName, std::vector<std::string>* warnings = nullptr,
                const Daylight& daylight = {}, std::vector<std::string>* notes = nullptr,
                UpChoice up = UpChoice::Format, std::vector<std::string>* readNotes = nullptr,
                double metresPerUnit = 0.0);

// --strict (radmesh's commands and radmesh-view): a scene that gave any warning as it was read (a
// repair, implausible --units: its loadScene `warnings`) is refused, a SceneError saying each and
// the fix; none, nothing happens.
void refuseWarnings(const std::string& pathOrName, const std::vector<std::string>& warnings);

}  // namespace radmesh
