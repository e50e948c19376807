#include "solver/io/atomic_file.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace radmesh {
namespace {

// What failed, with errno's reason, in words about the file asked for: the temporary file's name
// means nothing to whoever typed the path.
std::runtime_error failure(const std::string& what) {
  return std::runtime_error(fmt::format("{} ({})", what, std::strerror(errno)));
}

// A new temporary file beside path (named by the pid and a count, with the permissions the umask
// gives), open for writing.
struct TempFile {
  std::string path;
  int fd = -1;
};
TempFile createTempBeside(const std::string& path) {
  namespace fs = std::filesystem;
  static std::atomic<unsigned> count{0};
  const fs::path target(path);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  TempFile temp{(folder / fmt::format("{}.tmp-{}-{}", target.filename().string(), ::getpid(), count++)).string()};
  temp.fd = ::open(temp.path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (temp.fd < 0) {
    const int reason = errno;
    std::error_code ignored;  // a folder that is there but makes no file (/proc) is not said to be missing
    if (reason == ENOENT && !fs::is_directory(folder, ignored))
      throw std::runtime_error(fmt::format("the folder '{}' does not exist", folder.string()));
    errno = reason;
    throw failure(fmt::format("cannot make a file in the folder '{}'", folder.string()));
  }
  return temp;
}

// The file a link at `path` leads to (through every link), so that the rename replaces it and not
// the link; `path` itself where it is no link.
std::string throughLinks(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_symlink(path, error)) return path;
  const std::filesystem::path target = std::filesystem::weakly_canonical(path, error);
  return error ? path : target.string();
}

}  // namespace

void writeAtomically(const std::string& linkOrPath, const std::string& bytes) {
  const std::string path = throughLinks(linkOrPath);
  const TempFile temp = createTempBeside(path);
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(temp.fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  const bool flushed = done == bytes.size() && ::fsync(temp.fd) == 0;
  const int writeErrno = errno;
  ::close(temp.fd);
  std::string failed;
  if (!flushed) {
    errno = writeErrno;
    failed = "cannot write " + path;
  } else if (std::rename(temp.path.c_str(), path.c_str()) != 0) {
    failed = "cannot put the new " + path + " in place of the old";
  }
  if (!failed.empty()) {
    const std::runtime_error error = failure(failed);
    ::unlink(temp.path.c_str());
    throw error;
  }
  // The rename itself reaches the disk with the folder.
  const std::filesystem::path folder = std::filesystem::path(temp.path).parent_path();
  const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

void checkWritableBeside(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw std::runtime_error(fmt::format("{} is a folder: a file cannot replace it", path));
  const TempFile temp = createTempBeside(throughLinks(path));
  ::close(temp.fd);
  ::unlink(temp.path.c_str());
}

bool sameFile(const std::string& a, const std::string& b) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (fs::exists(a, error) && fs::exists(b, error)) return fs::equivalent(a, b, error);
  const fs::path left = fs::weakly_canonical(fs::absolute(a, error), error);
  const fs::path right = fs::weakly_canonical(fs::absolute(b, error), error);
  return !error && left == right;
}

}  // namespace radmesh
