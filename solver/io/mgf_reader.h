#pragma once
// MGF text to entities: one entity per line, a trailing backslash continues a line, a first
// word starting with '#' is a comment. Also the number parsing every MGF entity shares.
#include <string>
#include <vector>

namespace radmesh {

struct MgfEntity {
  int line = 0;                    // where the entity starts, 1-based, for messages
  std::vector<std::string> words;  // keyword first, never empty
};

// Reads a whole file. Throws SceneError when it cannot be read or ends inside a continued line.
std::vector<MgfEntity> readMgfEntities(const std::string& path);

// Throws MgfError unless the entity has between minimum and maximum arguments (words after the
// keyword); `usage` shows the right form, e.g. "rd rho_d".
void requireMgfArguments(const MgfEntity& entity, size_t minimum, size_t maximum, const std::string& usage);

// A finite number; throws MgfError naming `what` for text that is not one (NaN and inf included).
double parseMgfNumber(const std::string& word, const std::string& what);

// A whole number >= minimum; throws MgfError otherwise.
int parseMgfCount(const std::string& word, const std::string& what, int minimum);

}  // namespace radmesh
