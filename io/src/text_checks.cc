#include "text_checks.h"

#include <cstdio>

#include "uuvplan/model/input_error.h"

namespace uuvplan::io {

namespace {

std::string ByteName(unsigned char c) {
  char hex[8];
  std::snprintf(hex, sizeof hex, "0x%02x", c);
  return c == 0 ? std::string("a NUL byte (0x00)") : "the control byte " + std::string(hex);
}

}  // namespace

void CheckInputText(const std::string& path, const std::string& text, bool hash_comments) {
  int line = 1, depth = 0;
  char quote = 0;  // the open string's quote character
  bool comment = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n') {
      ++line;
      comment = false;
      continue;
    }
    if (c < 0x20 && c != '\t' && c != '\r') {
      throw model::InputError(path + ":" + std::to_string(line),
                              ByteName(c) + ": expected text (is this a binary file?)");
    }
    if (comment) continue;
    if (quote) {
      if (c == '\\' && quote == '"')
        ++i;  // an escaped character
      else if (c == static_cast<unsigned char>(quote))
        quote = 0;
      continue;
    }
    if (c == '"' || c == '\'')
      quote = static_cast<char>(c);
    else if (c == '#' && hash_comments)
      comment = true;
    else if (c == '[' || c == '{')
      ++depth;
    else if ((c == ']' || c == '}') && depth > 0)
      --depth;
    if (depth > kMaxNesting) {
      throw model::InputError(path + ":" + std::to_string(line),
                              "brackets [ ] or { } nested more than " +
                                  std::to_string(kMaxNesting) +
                                  " deep: expected a uuvplan file (they nest at most 4 deep)");
    }
  }
}

std::string WithoutQuotedInput(std::string message) {
  const std::size_t quoted = message.find("; last read: '");
  if (quoted != std::string::npos) message.erase(quoted);
  return message;
}

}  // namespace uuvplan::io
