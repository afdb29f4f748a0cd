// One check of an Options::IsValid: `ok`, or false with `message` in *error.
#pragma once

#include <string>
#include <string_view>

namespace uuvplan::ident {

inline bool Require(bool ok, std::string_view message, std::string* error) {
  if (!ok && error) *error = std::string(message);
  return ok;
}

}  // namespace uuvplan::ident
