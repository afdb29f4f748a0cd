// Where a value sits in an input file: the file, the 1-based line (0 where the format has no
// lines or the line is unknown) and the key path (`thrusters[1].thrust.c_pos`, `trials[2].force`,
// `column 't'`). Every reader of the io layer reports a fault through a Place, so that all
// messages have the contract's form "<file>:<line>: <key.path>: expected <what>, got <value>".
#pragma once

#include <cstddef>
#include <string>
#include <utility>

namespace uuvplan::io {

class Place {
 public:
  Place(std::string file, int line, std::string key_path)
      : file_(std::move(file)), line_(line), key_path_(std::move(key_path)) {}

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& key_path() const { return key_path_; }

  /// "file:line", or "file" when the line is unknown.
  std::string Where() const;

  /// Throws model::InputError "<Where()>: <key.path>: <what>" (no key path: "<Where()>: <what>").
  [[noreturn]] void Fail(const std::string& what) const;
  /// Fail("expected <expectation>, got <got>").
  [[noreturn]] void Expected(const std::string& expectation, const std::string& got) const;

  /// The key path of `key` inside this place (`a.b` + `c` -> `a.b.c`; top level -> `c`).
  std::string KeyPath(const std::string& key) const;
  /// The key path of item `index` of this list (`trials` -> `trials[2]`).
  std::string ItemPath(std::size_t index) const;

 private:
  std::string file_;
  int line_;
  std::string key_path_;
};

}  // namespace uuvplan::io
