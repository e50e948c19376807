#include "solver/io/output_path.h"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "solver/io/atomic_file.h"
#include "solver/io/builtin_scenes.h"
#include "solver/scene/scene_error.h"

namespace radmesh {

bool hasExtension(const std::string& path, const std::string& extension) {
  if (path.size() < extension.size()) return false;
  return std::equal(extension.begin(), extension.end(), path.end() - static_cast<std::ptrdiff_t>(extension.size()),
                    [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) ==
                                                std::tolower(static_cast<unsigned char>(b)); });
}

namespace {

void checkWritable(const std::string& option, const std::string& path) {
  try {
    checkWritableBeside(path);
  } catch (const std::runtime_error& e) {
    throw OptionError(fmt::format("{} '{}': cannot write there ({}): give a path in a writable folder with room",
                                  option, path, e.what()));
  }
}

// An output goes into a folder that exists: one is never made on the way, so a mistyped folder is
// refused with the fix rather than made and filled.
void checkFolderExists(const std::string& option, const std::string& path) {
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::error_code error;
  if (!folder.empty() && !std::filesystem::is_directory(folder, error))
    throw OptionError(fmt::format("{} '{}': the folder '{}' does not exist: create it (mkdir -p {}) or give "
                                  "another path",
                                  option, path, folder.string(), folder.string()));
}

}  // namespace

bool namesOnlyAnExtension(const std::string& path) {
  // "--out .glb" or "--checkpoint .ckpt" names no file but a hidden one: one dot, leading.
  const std::string name = std::filesystem::path(path).filename().string();
  return name.size() > 1 && name.front() == '.' && name.find('.', 1) == std::string::npos;
}

void checkOutputPath(const std::string& option, const std::string& path, const std::string& extension,
                     const std::string& what) {
  if (path.empty()) return;
  if (!hasExtension(path, extension))
    throw OptionError(fmt::format("{} '{}': {}: give a path ending in {}", option, path, what, extension));
  if (namesOnlyAnExtension(path)) {
    const std::string name = std::filesystem::path(path).filename().string();
    const std::filesystem::path example = std::filesystem::path(path).parent_path() /
                                          ("NAME" + (extension.empty() ? name : extension));
    throw OptionError(fmt::format("{} '{}': the file name is only the extension, which would write a hidden file "
                                  "named {}: give a name before it (e.g. {})",
                                  option, path, name, example.string()));
  }
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw OptionError(fmt::format("{} '{}' is a folder: give the path of a file in it", option, path));
  checkFolderExists(option, path);
  checkWritable(option, path);  // a folder that takes no file (read-only, full): now, not after the work
}

void makeOutputFolder(const std::string& option, const std::string& folder) {
  if (folder.empty()) return;  // the working folder
  std::filesystem::path named(folder);
  if (!named.has_filename()) named = named.parent_path();  // "out/" names the folder out
  checkFolderExists(option, named.string());
  std::error_code error;
  if (std::filesystem::create_directory(folder, error); !std::filesystem::is_directory(folder))
    throw OptionError(fmt::format("{} '{}': cannot make that folder ({}): give a folder you can write", option, folder,
                                  error ? error.message() : "a file is in its place"));
}

void checkOutputsDistinct(const std::string& scene, const std::vector<std::pair<std::string, std::string>>& outputs,
                          const std::string& resume) {
  const std::string file = sceneFile(scene);
  for (size_t i = 0; i < outputs.size(); ++i) {
    const auto& [option, path] = outputs[i];
    if (path.empty()) continue;
    if (!file.empty() && sameFile(path, file))
      throw OptionError(fmt::format("{} '{}' is the scene being solved: writing it would replace the scene; give "
                                    "another path", option, path));
    if (option != "--checkpoint" && !resume.empty() && sameFile(path, resume))
      throw OptionError(fmt::format("{} '{}' is the checkpoint --resume reads: writing it would replace the "
                                    "checkpoint; give another path", option, path));
    for (size_t j = 0; j < i; ++j)
      if (!outputs[j].second.empty() && sameFile(path, outputs[j].second))
        throw OptionError(fmt::format("{} '{}' is the file {} writes too: one would replace the other; give each "
                                      "its own path", option, path, outputs[j].first));
  }
}

}  // namespace radmesh
