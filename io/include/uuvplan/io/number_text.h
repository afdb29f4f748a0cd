// Numbers as text, read and written in one place for every format of the io layer. Reading
// takes a whole cell or scalar as a finite number; writing gives either the shortest text that
// reads back exactly (model::ShortestNumber, YAML and JSON) or `digits` significant digits as
// %.<digits>g would, without the locale (CSV columns). The readers are inline: the CSV reader
// calls them once per cell (bench/csv_read_bench.cc).
#pragma once

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <system_error>

#include "uuvplan/model/util/text.h"

namespace uuvplan::io {

using model::ShortestNumber;

/// `text` without leading and trailing blanks (spaces, tabs; a trailing '\r' too).
inline std::string_view TrimBlanks(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) {
    s.remove_suffix(1);
  }
  return s;
}

/// Parses the whole of `text` as a finite number (an optional leading '+' is allowed; NaN and
/// infinities are not numbers here). False if `text` is anything else.
inline bool ParseNumber(std::string_view text, double* value) {
  const char* first = text.data();
  const char* last = first + text.size();
  if (first != last && *first == '+') {
    ++first;
    if (first != last && *first == '-') return false;
  }
  const auto [end, ec] = std::from_chars(first, last, *value);
  return ec == std::errc() && end == last && first != last && std::isfinite(*value);
}

/// Appends `value` as %.<digits>g would, without the locale.
void AppendGeneral(double value, int digits, std::string* out);

}  // namespace uuvplan::io
