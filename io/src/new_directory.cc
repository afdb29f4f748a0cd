#include "uuvplan/io/new_directory.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <system_error>

#include "uuvplan/io/output_claim.h"
#include "uuvplan/model/input_error.h"

namespace uuvplan::io {

namespace fs = std::filesystem;
using model::InputError;

fs::path DirectoryPath(const std::string& dir) {
  fs::path out = fs::path(dir).lexically_normal();
  if (out.filename().empty()) out = out.parent_path();
  return out;
}

void CheckNewDirectory(const std::string& dir, const std::string& flag) {
  const fs::path out = DirectoryPath(dir);
  std::error_code ec;
  if (fs::exists(out) && !fs::is_empty(out, ec)) {
    throw InputError(dir, "output directory exists and is not empty; choose a new " + flag +
                              " (nothing is overwritten)");
  }
}

fs::path NewSiblingDirectory(const fs::path& out, const std::string& dir) {
  std::error_code ec;
  if (out.has_parent_path()) fs::create_directories(out.parent_path(), ec);
  std::string pattern = out.string() + ".tmp-uuvplan-XXXXXX";
  if (!::mkdtemp(pattern.data())) {
    throw InputError(
        dir, "cannot create a temporary directory beside it: " + std::string(std::strerror(errno)));
  }
  return pattern;
}

void MoveIntoPlace(const fs::path& tmp, const fs::path& out, const std::string& dir,
                   const std::string& what) {
  // Durable before visible: every directory of `tmp` synced, then one rename(2) over the empty
  // `out` (it replaces an empty directory atomically; the OutputClaim on `out`, when the caller
  // holds one, keeps other runs away), then the parent synced.
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(tmp, ec); !ec && it != fs::end(it);
       it.increment(ec)) {
    if (it->is_directory(ec)) SyncDirectory(it->path().string());
  }
  SyncDirectory(tmp.string());
  ec.clear();
  fs::rename(tmp, out, ec);
  if (!ec) {
    SyncDirectory(out.has_parent_path() ? out.parent_path().string() : ".");
    return;
  }
  std::error_code ignored;
  fs::remove_all(tmp, ignored);  // ours alone (NewSiblingDirectory)
  if (fs::exists(out)) {
    throw InputError(dir, "another run wrote " + what +
                              " there while this one was running; "
                              "nothing of this run was kept");
  }
  throw InputError(dir, "cannot move " + what + " into place: " + ec.message());
}

void WriteNewDirectory(const std::string& dir, const std::map<std::string, std::string>& files,
                       const std::string& flag, const std::string& what) {
  CheckNewDirectory(dir, flag);
  const fs::path out = DirectoryPath(dir);
  const fs::path tmp = NewSiblingDirectory(out, dir);
  std::error_code ec;
  try {
    for (const auto& [name, content] : files) {
      const fs::path file = tmp / name;
      fs::create_directories(file.parent_path(), ec);
      std::ofstream f(file, std::ios::binary);
      f.write(content.data(), static_cast<std::streamsize>(content.size()));
      f.close();
      if (!f) throw InputError((out / name).string(), "cannot write the file");
    }
    // mkdtemp made it private (0700): give it the permissions of a directory made by mkdir.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    fs::permissions(tmp, static_cast<fs::perms>(0777 & ~mask), ec);
  } catch (...) {
    fs::remove_all(tmp, ec);  // ours alone
    throw;
  }
  MoveIntoPlace(tmp, out, dir, what);
}

}  // namespace uuvplan::io
