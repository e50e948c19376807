#include "cli/output_file.h"

#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace radmesh::cli {

std::ofstream openOutput(const std::string& path) {
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::error_code ignored;  // a folder that cannot be made shows as the open failing below
  if (!folder.empty()) std::filesystem::create_directories(folder, ignored);
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot open for writing (check the folder is writable)");
  return out;
}

}  // namespace radmesh::cli
