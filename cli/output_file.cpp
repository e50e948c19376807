#include "cli/output_file.h"

#include <stdexcept>

namespace radmesh::cli {

std::ofstream openOutput(const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot open for writing (check the folder exists and is writable)");
  return out;
}

}  // namespace radmesh::cli
