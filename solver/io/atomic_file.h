#pragma once
// Files replaced whole or not at all (checkpoints): a kill at any moment leaves the old file or
// the new one, never a mix.
#include <string>

namespace radmesh {

// Writes bytes to a new temporary file beside path, flushes it to disk and renames it over path
// (over the file a link at path leads to, which stays a link).
// Throws std::runtime_error saying which step failed and why (e.g. "cannot create F.tmp-1-0:
// Permission denied"), leaving no temporary file behind.
void writeAtomically(const std::string& path, const std::string& bytes);

// Throws as writeAtomically would when path's folder cannot take a new file: to know before
// the work whose result it is to hold.
void checkWritableBeside(const std::string& path);

// Whether two paths name one file (the same file reached by links or relative paths included,
// and paths to files not yet written compared as they would resolve).
bool sameFile(const std::string& a, const std::string& b);

}  // namespace radmesh
