// Little-endian reading of a recording's bytes, every read checked against the end: a file
// cut short is model::InputError "<file>: byte <offset>: ...", never a read past the buffer.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "uuvplan/model/input_error.h"

namespace uuvplan::io::recording {

class ByteCursor {
 public:
  /// `bytes` start at byte `offset` of `file` (offsets in messages are the file's).
  ByteCursor(std::string_view bytes, const std::string& file, std::size_t offset = 0)
      : bytes_(bytes), file_(file), offset_(offset) {}

  bool AtEnd() const { return pos_ >= bytes_.size(); }
  std::size_t FileOffset() const { return offset_ + pos_; }
  std::size_t Remaining() const { return bytes_.size() - pos_; }

  template <typename T>
  T Read() {
    T value;
    std::memcpy(&value, Take(sizeof(T), "a number").data(), sizeof(T));  // little endian host
    return value;
  }
  /// The next `n` bytes; `what` names them in the fault of a short file.
  std::string_view Take(std::size_t n, const char* what) {
    if (n > Remaining()) {
      Fail("expected " + std::string(what) + " of " + std::to_string(n) +
           " bytes, got the end after " + std::to_string(Remaining()));
    }
    const std::string_view s = bytes_.substr(pos_, n);
    pos_ += n;
    return s;
  }
  [[noreturn]] void Fail(const std::string& what) const {
    throw model::InputError(file_ + ": byte " + std::to_string(FileOffset()), what);
  }
  const std::string& file() const { return file_; }

 private:
  std::string_view bytes_;
  const std::string& file_;
  std::size_t offset_;
  std::size_t pos_ = 0;
};

}  // namespace uuvplan::io::recording
