#include "cli/output_path.h"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "solver/scene/scene_error.h"

namespace radmesh::cli {

bool hasExtension(const std::string& path, const std::string& extension) {
  if (path.size() < extension.size()) return false;
  return std::equal(extension.begin(), extension.end(), path.end() - static_cast<std::ptrdiff_t>(extension.size()),
                    [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) ==
                                                std::tolower(static_cast<unsigned char>(b)); });
}

void checkOutputPath(const std::string& option, const std::string& path, const std::string& extension,
                     const std::string& what) {
  if (path.empty()) return;
  if (!hasExtension(path, extension))
    throw OptionError(fmt::format("{} '{}': {}: give a path ending in {}", option, path, what, extension));
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (folder.empty()) return;  // the current folder
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error))
    throw OptionError(fmt::format("{} '{}': the folder '{}' does not exist: create it (mkdir -p {}) or give "
                                  "another path",
                                  option, path, folder.string(), folder.string()));
}

}  // namespace radmesh::cli
