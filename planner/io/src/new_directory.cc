// A new directory written whole or not at all (files.h WriteNewDirectory).
#include <stdlib.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "uuvplan/io/files.h"
#include "uuvplan/model/input_error.h"

namespace uuvplan::io {

namespace fs = std::filesystem;

void WriteNewDirectory(const std::string& dir, const std::map<std::string, std::string>& files) {
  fs::path out = fs::path(dir).lexically_normal();
  if (out.filename().empty() && out.has_parent_path()) out = out.parent_path();
  std::error_code ec;
  if (fs::exists(out) && !(fs::is_directory(out) && fs::is_empty(out, ec))) {
    throw model::InputError(dir, "exists and is not an empty directory; choose a new one "
                                 "(nothing is overwritten)");
  }
  if (out.has_parent_path()) fs::create_directories(out.parent_path(), ec);
  std::string tmp = out.string() + ".tmp-uuvplan-XXXXXX";
  if (!::mkdtemp(tmp.data())) {
    throw model::InputError(dir, "cannot create a temporary directory beside it: " +
                                     std::string(std::strerror(errno)));
  }
  for (const auto& [name, text] : files) {
    std::ofstream f(fs::path(tmp) / name, std::ios::binary);
    f << text;
    if (!f.flush()) {
      fs::remove_all(tmp, ec);  // ours alone (mkdtemp)
      throw model::InputError(dir + "/" + name, "cannot write: " + std::string(std::strerror(errno)));
    }
  }
  if (fs::is_directory(out) && fs::is_empty(out, ec)) fs::remove(out, ec);
  fs::rename(tmp, out, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove_all(tmp, ignored);
    throw model::InputError(dir, "cannot move the directory into place: " + ec.message() +
                                     "; nothing of this run was kept");
  }
}

}  // namespace uuvplan::io
