#pragma once
// Work that can fail at the end is checked at the start: an output path is refused before a long
// solve, not after it.
#include <string>
#include <utility>
#include <vector>

namespace radmesh {

// Whether `path` ends in `extension` (e.g. ".glb"), in any case.
bool hasExtension(const std::string& path, const std::string& extension);

// Throws OptionError naming `option` and the fix when `path` does not end in `extension` (`what`
// says what the file is, e.g. "a bake is glTF binary") or its file name is that extension alone
// ("--out .glb" would write a hidden file), its folder does not exist, or no file can
// be written there (a folder without write permission, a file system that takes none: found by
// making and removing a file beside it), before the work whose output it is, not after. Empty: no
// file. `makeFolder`: a missing folder is made now (bench accuracy's outputs) rather than refused.
void checkOutputPath(const std::string& option, const std::string& path, const std::string& extension,
                     const std::string& what, bool makeFolder = false);

// Makes `folder` (and its parents) if missing, or throws OptionError naming `option` and why it
// cannot be made: before the work whose outputs it holds, not after.
void makeOutputFolder(const std::string& option, const std::string& folder);

// Throws OptionError when one of `outputs` (option, path; empty: no file) is the scene's own file
// (a built-in's asset too), the checkpoint `resume` reads (which only --checkpoint may replace, to
// go on saving there) or the same file as another: the later write would replace it without a word.
void checkOutputsDistinct(const std::string& scene, const std::vector<std::pair<std::string, std::string>>& outputs,
                          const std::string& resume = {});

}  // namespace radmesh
