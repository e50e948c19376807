#include "solver/io/file_signature.h"

#include <fstream>

namespace radmesh {

bool fileStartsWith(const std::string& path, std::string_view signature) {
  std::ifstream in(path, std::ios::binary);
  std::string head(signature.size(), '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  return in.gcount() == static_cast<std::streamsize>(signature.size()) && head == signature;
}

bool looksBinary(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head.find('\0') != std::string::npos;
}

}  // namespace radmesh
