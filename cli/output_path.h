#pragma once
// Work that can fail at the end is checked at the start: an output path is refused before a long
// solve, not after it.
#include <string>

namespace radmesh::cli {

// Whether `path` ends in `extension` (e.g. ".glb"), in any case.
bool hasExtension(const std::string& path, const std::string& extension);

// Throws OptionError naming `option` and the fix when `path` does not end in `extension` (`what`
// says what the file is, e.g. "a bake is glTF binary") or its folder does not exist. Empty: no file.
void checkOutputPath(const std::string& option, const std::string& path, const std::string& extension,
                     const std::string& what);

}  // namespace radmesh::cli
