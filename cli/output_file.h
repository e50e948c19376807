#pragma once
// Every file the commands write is opened here, so that a missing folder is made and a failure names the file.
#include <fstream>
#include <string>

namespace radmesh::cli {

// Creates the folder of `path` when missing; throws std::runtime_error naming `path` when it cannot be written.
std::ofstream openOutput(const std::string& path);

}  // namespace radmesh::cli
