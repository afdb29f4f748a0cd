#include "uuvplan/io/place.h"

#include "uuvplan/model/input_error.h"

namespace uuvplan::io {

std::string Place::Where() const { return line_ > 0 ? file_ + ":" + std::to_string(line_) : file_; }

void Place::Fail(const std::string& what) const {
  throw model::InputError(Where(), key_path_.empty() ? what : key_path_ + ": " + what);
}

void Place::Expected(const std::string& expectation, const std::string& got) const {
  Fail("expected " + expectation + ", got " + got);
}

std::string Place::KeyPath(const std::string& key) const {
  return key_path_.empty() ? key : key_path_ + "." + key;
}

std::string Place::ItemPath(std::size_t index) const {
  return key_path_ + "[" + std::to_string(index) + "]";
}

}  // namespace uuvplan::io
