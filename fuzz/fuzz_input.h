// What every fuzz target shares: the fuzzed bytes as a file (the readers take paths), in a
// directory of this process that also holds the valid files a campaign may name
// (vehicle.yaml, pool.yaml, trials/*.csv from tests/data/io), and the one rule: a reader
// returns or throws model::InputError, nothing else.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include "uuvplan/model/input_error.h"

namespace uuvplan::fuzz {

/// A directory of this process, with copies of tests/data/io's vehicle, pool and trials.
inline const std::string& Scratch() {
  static const std::string dir = [] {
    namespace fs = std::filesystem;
    std::string pattern = (fs::temp_directory_path() / "uuvplan-fuzz-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) std::abort();
    const fs::path io = fs::path(UUVPLAN_SOURCE_DIR) / "tests/data/io";
    fs::copy(io, pattern, fs::copy_options::recursive);
    return pattern;
  }();
  return dir;
}

/// Writes the input to `<scratch>/<name>` and returns its path.
inline std::string WriteInput(const uint8_t* data, size_t size, const std::string& name) {
  const std::string path = Scratch() + "/" + name;
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

/// Runs `read`; model::InputError is the expected outcome of a bad input, anything else aborts
/// with what it was (libFuzzer then saves the input).
template <typename Read>
void ExpectOnlyInputErrors(Read read) {
  try {
    read();
  } catch (const model::InputError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "reader threw something else than InputError: %s\n", e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "reader threw a non-std exception\n");
    std::abort();
  }
}

}  // namespace uuvplan::fuzz
