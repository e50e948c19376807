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

FileKind fileKind(const std::filesystem::path& path) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) return FileKind::Missing;
  if (std::filesystem::is_regular_file(status)) return FileKind::Regular;
  return std::filesystem::is_directory(status) ? FileKind::Folder : FileKind::Special;
}

std::string fileKindName(FileKind kind) {
  switch (kind) {
    case FileKind::Missing: return "missing";
    case FileKind::Regular: return "a file";
    case FileKind::Folder: return "a folder";
    case FileKind::Special: return "a FIFO, socket or device";
  }
  return "";
}

}  // namespace radmesh
