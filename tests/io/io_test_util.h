// Helpers of the reader/writer tests: a scratch copy of tests/data/io that a test may edit,
// and the message of the InputError a call throws.
#pragma once

#include <gtest/gtest.h>
#include <stdlib.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "uuvplan/model/input_error.h"

namespace uuvplan::model::testing {

inline std::string SourcePath(const std::string& relative) {
  return std::string(UUVPLAN_SOURCE_DIR) + "/" + relative;
}

inline std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void WriteText(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

/// A fresh copy of tests/data/io in a temporary directory, removed at the end of the test.
class ScratchDir {
 public:
  ScratchDir() {
    std::string pattern = ::testing::TempDir() + "uuvplan_io_XXXXXX";
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp " + pattern);
    root_ = pattern;
    std::filesystem::copy(SourcePath("tests/data/io"), root_,
                          std::filesystem::copy_options::recursive);
  }
  ~ScratchDir() { std::filesystem::remove_all(root_); }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  std::string Path(const std::string& relative) const { return root_ + "/" + relative; }

  /// Replaces the only occurrence of `from` in `relative` by `to`; returns its 1-based line.
  int Edit(const std::string& relative, const std::string& from, const std::string& to) {
    std::string text = ReadText(Path(relative));
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "'" << from << "' not in " << relative;
    EXPECT_EQ(text.find(from, at + 1), std::string::npos)
        << "'" << from << "' twice in " << relative;
    if (at == std::string::npos) return 0;
    const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
    text.replace(at, from.size(), to);
    WriteText(Path(relative), text);
    return line;
  }

  /// Writes `text` to `relative`; returns its path.
  std::string Write(const std::string& relative, const std::string& text) const {
    WriteText(Path(relative), text);
    return Path(relative);
  }

 private:
  std::string root_;
};

/// The message of the InputError that `read` throws (a test failure if it throws none).
template <typename Read>
std::string ErrorOf(Read read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError thrown";
  return "";
}

/// "<file>:<line>:" as the readers write it.
inline std::string At(const std::string& file, int line) {
  return file + ":" + std::to_string(line) + ":";
}

}  // namespace uuvplan::model::testing
