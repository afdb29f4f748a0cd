// Bad user input: a file, a place in it (line or YAML key) and what was expected.
// Readers throw InputError; the command line turns it into exit status 2.
#pragma once

#include <stdexcept>
#include <string>

namespace uuvplan::model {

class InputError : public std::runtime_error {
 public:
  /// `where` is "file:line" or "file: key.path"; `what` says what was expected.
  InputError(const std::string& where, const std::string& what)
      : std::runtime_error(where.empty() ? what : where + ": " + what) {}
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace uuvplan::model
