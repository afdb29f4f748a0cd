// Whole-or-nothing output files: the text goes to a temporary file in the target's directory
// (so that the final rename stays within one file system and is atomic), then replaces the
// target. A reader of `path` sees either the old file or the complete new one; file and
// directory are fsync'ed before and after the rename. A symbolic link is written through (the
// file it names is replaced, the link stays); an existing special file (a device such as
// /dev/null, a FIFO) is written in place, never replaced by a regular file.
#include <fcntl.h>
#include <limits.h>
#include <sys/stat.h>
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

// Writes `text` to `fd` (then fsync(2) it when `sync`) and closes it: "" when all of it went,
// else the system's reason for the first failure.
std::string WriteAndClose(int fd, const std::string& text, bool sync) {
  const bool written = WriteAll(fd, text) && (!sync || ::fsync(fd) == 0);
  const int write_errno = errno;
  const bool closed = ::close(fd) == 0;
  if (written && closed) return "";
  return std::strerror(written ? errno : write_errno);
}

// The file a chain of symbolic links ends at (relative links resolved against the directory of
// the link), or `path` itself when it is not a link. The last target need not exist: writing
// through a dangling link creates the file it names.
std::string ThroughLinks(const std::string& path) {
  std::filesystem::path p(path);
  for (int hop = 0; hop < 40; ++hop) {  // 40: Linux's own limit on links followed (MAXSYMLINKS)
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p.string();
    char target[PATH_MAX];
    const ssize_t n = ::readlink(p.c_str(), target, sizeof target - 1);
    if (n < 0) throw model::InputError(path, "cannot read the symbolic link: " + ErrnoText());
    const std::filesystem::path next(std::string(target, static_cast<std::size_t>(n)));
    p = next.is_absolute() ? next : p.parent_path() / next;
  }
  throw model::InputError(path, "cannot write through it: too many levels of symbolic links");
}

// A device, FIFO or socket at `path` is written as it stands: open(2) without O_CREAT, so that
// the node itself is never replaced; a write error (ENOSPC on /dev/full) is an error.
void WriteInPlace(const std::string& path, const std::string& text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) throw model::InputError(path, "cannot open it for writing: " + ErrnoText());
  const std::string reason = WriteAndClose(fd, text, false);
  if (!reason.empty()) throw model::InputError(path, "cannot write: " + reason);
}

}  // namespace

void WriteFileAtomically(const std::string& requested, const std::string& text) {
  // stat(2) follows links: a link to a pipe (/dev/fd/63 of `--json >(jq .)`) is written in place.
  struct stat existing {};
  const bool exists = ::stat(requested.c_str(), &existing) == 0;
  if (exists && !S_ISREG(existing.st_mode) && !S_ISDIR(existing.st_mode)) {
    WriteInPlace(requested, text);
    return;
  }
  const std::string path = ThroughLinks(requested);
  const std::string label = path == requested ? path : requested + " (a link to " + path + ")";
  std::string temp;
  const int fd = CreateTemporary(path, &temp);
  if (fd < 0)
    throw model::InputError(label, "cannot create a temporary file beside it: " + ErrnoText());
  if (exists && S_ISREG(existing.st_mode)) ::fchmod(fd, existing.st_mode & 0777);  // kept
  // The data reaches the disk before the rename makes it the file: after a crash the target
  // is the old file or the whole new one, never an empty one.
  if (const std::string reason = WriteAndClose(fd, text, true); !reason.empty()) {
    ::unlink(temp.c_str());
    throw model::InputError(label, "cannot write: " + reason);
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    const std::string reason = ErrnoText();
    ::unlink(temp.c_str());
    throw model::InputError(label, "cannot replace it with the new file: " + reason);
  }
  SyncDirectory(std::filesystem::path(path).parent_path().string());  // the rename itself
}

}  // namespace uuvplan::io
