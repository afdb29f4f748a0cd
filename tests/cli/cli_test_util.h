// Helpers of the tool tests: a temporary directory removed at the end of the test, running the
// uuvplan binary with its exit status and output, and reading files.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace uuvplan::cli_test {

/// cases/romeo/ of the source tree, with its trailing slash.
inline const std::string kRomeoCase = std::string(UUVPLAN_SOURCE_DIR) + "/cases/romeo/";

/// A new empty directory under the system's temporary directory, removed with its contents.
class TempDir {
 public:
  TempDir() {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "uuvplan-tooltest-XXXXXX").string();
    if (mkdtemp(pattern.data()) != nullptr) path_ = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    if (!path_.empty()) std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::string& path() const { return path_; }
  std::string operator/(const std::string& name) const { return path_ + "/" + name; }
  /// Writes `text` to `name` inside the directory; returns its path.
  std::string Write(const std::string& name, const std::string& text) const {
    const std::string p = *this / name;
    std::ofstream(p) << text;
    return p;
  }

 private:
  std::string path_;
};

inline std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The result of running the tool: exit status, stdout and stderr.
struct ToolRun {
  int status = -1;
  std::string out;
  std::string err;
};

/// Runs `UUVPLAN_BINARY <args>` (args are passed to the shell as written; quote paths with
/// spaces) with stdout and stderr captured in files of `scratch`.
inline ToolRun RunTool(const std::string& args, const TempDir& scratch) {
  const std::string out = scratch / "stdout.txt";
  const std::string err = scratch / "stderr.txt";
  const std::string command =
      std::string("'") + UUVPLAN_BINARY + "' " + args + " >'" + out + "' 2>'" + err + "'";
  const int raw = std::system(command.c_str());
  ToolRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = ReadText(out);
  r.err = ReadText(err);
  return r;
}

/// The pool team's first hour on ROMEO (cases/romeo): three short surge trials, a steady run
/// each way and a sine, as a plan for `simulate --plan`.
inline constexpr const char* kRomeoFirstSurgeTrials = R"({"trials": [
  {"id": "surge_steady", "dof": "surge", "kind": "steady", "duration": 20,
   "mapping": "surge-front", "force": 35},
  {"id": "surge_back", "dof": "surge", "kind": "steady", "duration": 20,
   "mapping": "surge-rear", "force": -35},
  {"id": "surge_sine", "dof": "surge", "kind": "sine", "duration": 30, "mapping": "surge-front",
   "offset": 30, "amplitude": 20, "omega": 0.4}]})";

}  // namespace uuvplan::cli_test
