#pragma once
// The first bytes that say what a file is, whatever its name says.
#include <filesystem>
#include <string>
#include <string_view>

namespace radmesh {

// A radmesh checkpoint (solver/radiosity/checkpoint.h) starts with these eight bytes.
inline constexpr std::string_view kCheckpointSignature{"RADMESHC", 8};

// A glTF binary (.glb) starts with these four bytes.
inline constexpr std::string_view kGlbSignature{"glTF", 4};

// Does the file at `path` start with `signature`? False when it is shorter or cannot be read.
bool fileStartsWith(const std::string& path, std::string_view signature);

// Does its first 4 KB hold a NUL byte, which no text file has?
bool looksBinary(const std::string& path);

// What a path names. A reader must refuse a folder, and a FIFO, socket or device too: reading
// one blocks until a writer comes, or never ends.
enum class FileKind { Missing, Regular, Folder, Special };
FileKind fileKind(const std::filesystem::path& path);
// A kind that is no file, for messages: "a folder", "a FIFO, socket or device".
std::string fileKindName(FileKind kind);

}  // namespace radmesh
