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

/// Significant digits a file keeps of a number: a person reads it, and 10 digits are 1e-10
/// relative, far below any measurement the files hold.
constexpr int kFileDigits = 10;

/// A number in a file people read: the shortest text that reads back exactly when that has at
/// most kFileDigits significant digits ("0.1", "6.621"), else kFileDigits digits.
std::string FileNumber(double value);

/// The 1σ of an estimate in a file: 2 significant digits ("0.073"), 0 as "0".
std::string SigmaNumber(double sigma);

/// An estimate in a file, rounded one digit past its σ's second significant digit ("0.5751"
/// for 0.575123 ± 0.073): the digits that carry information plus a guard digit, so that the
/// rounding (at most σ/200) moves what is computed from the file by far less than its σ says —
/// the BlueROV yaw model's held-out velocity MAE moved 1.2e-3 relative when rounded at the
/// second digit (σ/20), against ~1e-4 here. A σ that is 0 or not finite leaves
/// FileNumber(value).
std::string EstimateNumber(double value, double sigma);

}  // namespace uuvplan::io
