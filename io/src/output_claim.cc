#include "uuvplan/io/output_claim.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <set>

#include "uuvplan/model/input_error.h"

namespace uuvplan::io {

namespace fs = std::filesystem;

namespace {

// The directories this process has claimed (flock conflicts between two descriptors of one
// process too: a nested claim must not lock again).
std::set<std::string>& Claimed() {
  static std::set<std::string> claimed;
  return claimed;
}
std::mutex& ClaimedMutex() {
  static std::mutex mutex;
  return mutex;
}

std::string Normal(const std::string& dir) {
  fs::path p = fs::absolute(fs::path(dir)).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();
  return p.string();
}

bool IsEmptyDirectory(const std::string& path) {
  std::error_code ec;
  return fs::is_directory(path, ec) && fs::is_empty(path, ec);
}

}  // namespace

OutputClaim::OutputClaim(const std::string& dir) : path_(Normal(dir)) {
  const std::lock_guard<std::mutex> guard(ClaimedMutex());
  if (Claimed().count(path_)) return;  // nested
  std::error_code ec;
  if (fs::exists(path_, ec) && !IsEmptyDirectory(path_)) {
    throw model::InputError(dir,
                            "output directory exists and is not empty; choose a new --out "
                            "(nothing is overwritten)");
  }
  if (const fs::path parent = fs::path(path_).parent_path(); !parent.empty()) {
    fs::create_directories(parent, ec);
  }
  created_ = ::mkdir(path_.c_str(), 0777) == 0;
  fd_ = ::open(path_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0)
    throw model::InputError(
        dir, "cannot create the output directory: " + std::string(std::strerror(errno)));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    throw model::InputError(
        dir, "another run is writing " + dir + "; wait for it to finish or choose another --out");
  }
  // Claimed; another run may have finished its campaign here since the check above.
  if (!IsEmptyDirectory(path_)) {
    ::close(fd_);
    throw model::InputError(dir,
                            "another run wrote a campaign there; choose a new --out "
                            "(nothing is overwritten)");
  }
  Claimed().insert(path_);
}

OutputClaim::~OutputClaim() {
  if (fd_ < 0) return;
  const std::lock_guard<std::mutex> guard(ClaimedMutex());
  std::error_code ec;
  if (created_ && IsEmptyDirectory(path_)) fs::remove(path_, ec);  // an empty directory only
  Claimed().erase(path_);
  ::close(fd_);  // releases the lock
}

void SyncDirectory(const std::string& dir) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace uuvplan::io
