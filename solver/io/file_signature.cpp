#include "solver/io/file_signature.h"

#include <fstream>

namespace radmesh {

bool fileStartsWith(const std::string& path, std::string_view signature) {
  std::ifstream in(path, std::ios::binary);
  std::string head(signature.size(), '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  return in.gcount() == static_cast<std::streamsize>(signature.size()) && head == signature;
}

}  // namespace radmesh
