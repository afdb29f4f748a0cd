// Whole-or-nothing output files: the text goes to a temporary file in the target's directory
// (so that the final rename stays within one file system and is atomic), then replaces the
// target. A reader of `path` sees either the old file or the complete new one; file and
// directory are fsync'ed before and after the rename.
#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

#include "uuvplan/io/files.h"
#include "uuvplan/io/output_claim.h"
#include "uuvplan/model/input_error.h"

namespace uuvplan::io {

namespace {

std::string ErrnoText() { return std::strerror(errno); }

// Creates `<dir>/.<name>.tmp-<pid>-<n>` exclusively (mode 0666 less the umask, like the
// target would get). Returns the descriptor, or -1 with errno set.
int CreateTemporary(const std::string& path, std::string* temp_path) {
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path target(path);
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string name = "." + target.filename().string() + ".tmp-" +
                             std::to_string(::getpid()) + "-" + std::to_string(counter++);
    *temp_path = (target.parent_path() / name).string();
    const int fd = ::open(temp_path->c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  return -1;
}

bool WriteAll(int fd, const std::string& text) {
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

void WriteFileAtomically(const std::string& path, const std::string& text) {
  std::string temp;
  const int fd = CreateTemporary(path, &temp);
  if (fd < 0)
    throw model::InputError(path, "cannot create a temporary file beside it: " + ErrnoText());
  // The data reaches the disk before the rename makes it the file: after a crash the target
  // is the old file or the whole new one, never an empty one.
  const bool written = WriteAll(fd, text) && ::fsync(fd) == 0;
  const int write_errno = errno;
  const bool closed = ::close(fd) == 0;
  if (!written || !closed) {
    const std::string reason = std::strerror(written ? errno : write_errno);
    ::unlink(temp.c_str());
    throw model::InputError(path, "cannot write: " + reason);
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    const std::string reason = ErrnoText();
    ::unlink(temp.c_str());
    throw model::InputError(path, "cannot replace it with the new file: " + reason);
  }
  SyncDirectory(std::filesystem::path(path).parent_path().string());  // the rename itself
}

}  // namespace uuvplan::io
