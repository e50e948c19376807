#pragma once
// Every file the commands write is opened here, so that a failure names the file.
#include <fstream>
#include <string>

namespace radmesh::cli {

// Opens `path` for writing; throws std::runtime_error naming `path` when it cannot be. Its folder is
// not made: the command checked it before its work (checkOutputPath, solver/io/output_path.h).
std::ofstream openOutput(const std::string& path);

}  // namespace radmesh::cli
