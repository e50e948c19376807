#pragma once
// Work that can fail at the end is checked at the start: an output path is refused before a long
// solve, not after it.
#include <string>
#include <utility>
#include <vector>

namespace radmesh {

// Whether `path` ends in `extension` (e.g. ".glb"), in any case.
bool hasExtension(const std::string& path, const std::string& extension);

// Whether the file name of `path` is an extension alone (".glb", ".ckpt"): it would write a hidden
// file, where a name was surely meant.
bool namesOnlyAnExtension(const std::string& path);

// Throws OptionError naming `option` and the fix when `path` does not end in `extension` (`what`
// says what the file is, e.g. "a bake is glTF binary"; "": any name), its file name is an extension
// alone (".glb", ".ckpt": it would write a hidden file), its folder does not exist (refused, not
// made: a mistyped folder is found, not filled), or no file can be written there (a folder without
// write permission, a file system that takes none: found by making and removing a file beside it),
// before the work whose output it is, not after. Empty: no file.
void checkOutputPath(const std::string& option, const std::string& path, const std::string& extension,
                     const std::string& what);

// For an option that names a folder of outputs (--out-dir): makes `folder` if missing, in a folder
// that exists (as a file is made in one: checkOutputPath), or throws OptionError naming `option` and
// why it cannot be: before the work whose outputs it holds, not after. Empty: the working folder.
void makeOutputFolder(const std::string& option, const std::string& folder);

// Throws OptionError when one of `outputs` (option, path; empty: no file) is the scene's own file
// (a built-in's asset too), the checkpoint `resume` reads (which only --checkpoint may replace, to
// go on saving there) or the same file as another: the later write would replace it without a word.
void checkOutputsDistinct(const std::string& scene, const std::vector<std::pair<std::string, std::string>>& outputs,
                          const std::string& resume = {});

}  // namespace radmesh
