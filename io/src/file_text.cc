// Reading whole input files and resolving the paths one file gives to another.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "uuvplan/io/files.h"
#include "uuvplan/model/input_error.h"

namespace uuvplan::io {

namespace fs = std::filesystem;

std::string UnreadableReason(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) return "it is a directory";
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) return std::strerror(errno);
  std::fclose(file);
  return "";
}

std::string ReadFileText(const std::string& path) {
  if (const std::string reason = UnreadableReason(path); !reason.empty()) {
    throw model::InputError(path, "cannot open file: " + reason);
  }
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string ResolveBeside(const std::string& base_file, const std::string& file) {
  const fs::path p(file);
  if (p.is_absolute()) return file;
  return (fs::path(base_file).parent_path() / p).lexically_normal().string();
}

}  // namespace uuvplan::io
